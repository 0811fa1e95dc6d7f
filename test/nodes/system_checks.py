"""What rostest checkers see of the running system from outside (not a test
by itself): its nodes in the master's graph, their pids, a node killed as a
crash would, and the world held still while a check waits on wall time."""
import contextlib
import os
import signal
import time
import xmlrpc.client

import rosgraph
import rospy
from std_srvs.srv import Empty


@contextlib.contextmanager
def world_held():
    """The world paused for the block (Gazebo's pause_physics), for a check
    that waits on wall time (a throttle's second, a respawn): at
    real_time_factor 0 the simulator would otherwise step through it at up
    to 20x, a simulated minute of CPU for nothing. ROS time stands still in
    the block; nodes and their wall-time throttles go on."""
    rospy.wait_for_service('/gazebo/pause_physics', timeout=30.0)
    rospy.ServiceProxy('/gazebo/pause_physics', Empty)()
    try:
        yield
    finally:
        rospy.ServiceProxy('/gazebo/unpause_physics', Empty)()


def wall_until(predicate, wall_seconds=10.0):
    """True once ``predicate()`` holds (asked every 20 ms), False after
    ``wall_seconds``: the wait for a held world (:func:`world_held`), where
    ROS time stands still and a wait in ROS time would never end."""
    end = time.monotonic() + wall_seconds
    while not predicate():
        if time.monotonic() >= end:
            return False
        time.sleep(0.02)
    return True


def wait_for_every_subscriber(pub, wall_seconds=20.0):
    """Wait (wall time: connections take wall time) until ``pub`` is connected
    to every subscriber the master lists for its topic."""
    master = rosgraph.Master(rospy.get_name())
    deadline = time.monotonic() + wall_seconds
    while time.monotonic() < deadline:
        subscribers = dict(master.getSystemState()[1]).get(pub.resolved_name, [])
        if subscribers and pub.get_num_connections() >= len(subscribers):
            return
        time.sleep(0.05)
    raise AssertionError('%s: %d connections, subscribers %s' % (
        pub.resolved_name, pub.get_num_connections(), subscribers))


def wait_for_graph(topic, node, role='subscriber', wall_seconds=30.0):
    """Wait (wall time, asking the master twice a second) until ``node`` is a
    ``role`` ('subscriber' or 'publisher') of ``topic``: for a message that two
    other nodes must pass on, which no topic of the checker can tell."""
    master = rosgraph.Master(rospy.get_name())
    end = time.monotonic() + wall_seconds
    index = 1 if role == 'subscriber' else 0
    while time.monotonic() < end and not rospy.is_shutdown():
        entries = dict(master.getSystemState()[index])
        if node in entries.get(topic, []):
            return
        time.sleep(0.5)
    raise AssertionError('%s is not a %s of %s after %.0f s' % (node, role, topic,
                                                                 wall_seconds))


def kill_node(name):
    """SIGKILL a node (as a crash would); returns its pid."""
    uri = rosgraph.Master('/checker').lookupNode(name)
    pid = xmlrpc.client.ServerProxy(uri).getPid('/checker')[2]
    os.kill(pid, signal.SIGKILL)
    return pid


def node_pid(name):
    """The pid of a running node, or None."""
    try:
        uri = rosgraph.Master('/checker').lookupNode(name)
        return xmlrpc.client.ServerProxy(uri).getPid('/checker')[2]
    except (rosgraph.MasterError, OSError, xmlrpc.client.Error):
        return None         # not running (yet, or any more)

"""What the rostest checker nodes share (not a test by itself).

Waits are events: each subscriber notifies a :class:`RosClock` and a check
waits on it with a deadline in ROS time (the simulator's), so nothing polls;
the .test file's time-limit bounds every run in wall time.
"""
import math
import threading
import time
import unittest

import actionlib
import rosgraph
import rospy
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import JointState
from std_msgs.msg import String

from exp_assignment2.geometry import yaw_of
from exp_assignment2.ros.clock import RosClock

_clock = None


def clock():
    """The checker's clock (one per process, after rospy.init_node)."""
    global _clock
    if _clock is None:
        _clock = RosClock()
    return _clock


# a window of ROS time lasts at least as long as at this many times real time
FASTEST = 5.0


def wait_until(predicate, ros_seconds):
    """True once ``predicate()`` holds, False after ``ros_seconds`` of ROS time
    (counted once ROS time runs) and at least ``ros_seconds / FASTEST`` of
    wall time: at real_time_factor 0 (up to 20x) a node that waits a tenth of
    a wall second for its CPU on a loaded machine is two simulated seconds
    late, and a window sized for the behaviour must not also have to cover
    that. To check that something does not happen within a window of ROS
    time, use ``clock().wait_until`` (exact)."""
    clock().wait_for_time()
    wall_end = time.monotonic() + ros_seconds / FASTEST
    if clock().wait_until(predicate, ros_seconds):
        return True
    while time.monotonic() < wall_end:
        if clock().wait_until(predicate, 0.1):
            return True
    return False


def eventually(predicate, ros_seconds=10.0, wall_seconds=10.0):
    """True once ``predicate()`` holds; False only after both ``ros_seconds``
    of ROS time and ``wall_seconds`` of wall time: for what takes wall time
    too (a connection, a debounce), which at real_time_factor 0 is many
    simulated seconds."""
    wall_end = time.monotonic() + wall_seconds
    while True:
        if wait_until(predicate, ros_seconds):
            return True
        if time.monotonic() >= wall_end:
            return False


class SimpleClient(actionlib.SimpleActionClient):
    """actionlib's SimpleActionClient without its race: a server that answers
    before ``send_goal`` has stored the new goal's handle (a ball already where
    the goal puts it: at once) had its answer dropped ("Got a transition
    callback on a goal handle that we're not tracking"), and the goal never
    ended for the client. Storing the handle and handling a transition exclude
    each other here."""

    def __init__(self, *args, **kwargs):
        actionlib.SimpleActionClient.__init__(self, *args, **kwargs)
        self._sending = threading.RLock()

    def send_goal(self, *args, **kwargs):
        with self._sending:
            actionlib.SimpleActionClient.send_goal(self, *args, **kwargs)

    def _handle_transition(self, gh):
        with self._sending:
            actionlib.SimpleActionClient._handle_transition(self, gh)

    def _handle_feedback(self, gh, feedback):
        with self._sending:
            actionlib.SimpleActionClient._handle_feedback(self, gh, feedback)


def finished(client, ros_seconds, wall_seconds=10.0):
    """True once the goal of a SimpleActionClient is done: after its result,
    or after ``ros_seconds`` of ROS time and ``wall_seconds`` of wall time (a
    refusal or a preemption takes wall time, not ROS time)."""
    return eventually(lambda: client.simple_state == actionlib.SimpleGoalState.DONE,
                      ros_seconds, wall_seconds)


class Watch(object):
    """The latest message of a topic (and, with ``keep``, all of them)."""

    def __init__(self, topic, cls, keep=False):
        self.msg, self.count, self.all = None, 0, [] if keep else None
        self.lock = threading.Lock()
        self.topic = topic
        self.sub = rospy.Subscriber(topic, cls, self._cb, queue_size=100)

    def connected(self, node, wall_seconds=20.0):
        """Wait (wall time) until ``node`` publishing the topic is connected
        to us: what it publishes from then on reaches us (not latched topics
        lose what comes before)."""
        master = rosgraph.Master(rospy.get_name())
        deadline = time.monotonic() + wall_seconds
        while time.monotonic() < deadline:
            publishers = dict(master.getSystemState()[0]).get(self.topic, [])
            if node in publishers and self.sub.get_num_connections() >= len(publishers):
                return True
            time.sleep(0.05)
        raise AssertionError('%s never connected its %s to us' % (node, self.topic))

    def _cb(self, msg):
        with self.lock:
            self.msg, self.count = msg, self.count + 1
            if self.all is not None:
                self.all.append(msg)
        clock().notify()
        self.on_message(msg)

    def on_message(self, msg):
        pass

    def after(self, stamp, ros_seconds=10.0):
        """The first message stamped after ``stamp`` (s of ROS time)."""
        assert wait_until(lambda: self.msg is not None
                          and self.msg.header.stamp.to_sec() > stamp, ros_seconds), \
            'no message after %.2f s' % stamp
        return self.msg

    def next(self, ros_seconds=10.0):
        """The first message after now."""
        count = self.count
        assert wait_until(lambda: self.count > count, ros_seconds), 'no message in %.0f s' % (
            ros_seconds)
        return self.msg


class Rosout(Watch):
    """Every log line of every node, from /rosout."""

    def __init__(self):
        Watch.__init__(self, '/rosout', Log, keep=True)

    def lines(self, text='', level=None, node=None):
        with self.lock:
            return [m for m in self.all if text in m.msg and (level is None or m.level == level)
                    and (node is None or m.name == node)]


class Pose(Watch):
    """An Odometry topic as (x, y, z, yaw)."""

    def __init__(self, topic):
        Watch.__init__(self, topic, Odometry)

    def xyzyaw(self):
        p, q = self.msg.pose.pose.position, self.msg.pose.pose.orientation
        return p.x, p.y, p.z, yaw_of((q.x, q.y, q.z, q.w))


def wait_for_subscribers(pub, ros_seconds=30.0):
    """True once ``pub`` has a subscriber (bounded)."""
    ok = wait_until(lambda: pub.get_num_connections() > 0, ros_seconds)
    assert ok, 'nobody subscribes to %s' % pub.resolved_name
    return ok


class DogObserver(object):
    """Everything a scenario-A checker looks at: states, poses, head.

    ``states`` are the labels of the latched ``/robot/state`` (every one: the
    state machine queues 10) with the checker's ROS time at arrival; for
    timings, :meth:`logged` has the state machine's own stamps ('state: X'
    on /rosout)."""

    def __init__(self, rosout=None):
        self.states, self.head_positions = [], []      # (ros time, label); rad
        self.rosout = rosout or Rosout()
        self.robot, self.ball = Pose('/robot/odom'), Pose('/ball/odom')
        rospy.Subscriber('/robot/state', String, self._on_state, queue_size=10)
        rospy.Subscriber('/robot/joint_states', JointState, self._on_joints, queue_size=50)

    def _on_state(self, msg):
        self.states.append((rospy.get_time(), msg.data))
        clock().notify()

    def _on_joints(self, msg):
        if 'head_joint' in msg.name:
            self.head_positions.append(msg.position[msg.name.index('head_joint')])

    def state(self):
        return self.states[-1][1] if self.states else None

    def entered(self, label, after=None):
        """When ``label`` arrived (checker's ROS time), the arrivals after ``after``."""
        return [t for t, s in self.states if s == label and (after is None or t > after)]

    def logged(self, label, after=None):
        """When the state machine entered ``label`` (its stamps), after ``after``."""
        stamps = [m.header.stamp.to_sec() for m in self.rosout.lines('state: ' + label,
                                                                     node='/state_machine')
                  if m.msg == 'state: ' + label]
        return [t for t in stamps if after is None or t > after]

    def ball_distance(self):
        if self.robot.msg is None or self.ball.msg is None:
            return float('inf')
        r, b = self.robot.xyzyaw(), self.ball.xyzyaw()
        return math.hypot(r[0] - b[0], r[1] - b[1])

    def head_reached(self, angle, tolerance):
        return any(abs(h - angle) <= tolerance for h in self.head_positions)


class DogCheck(unittest.TestCase):
    """A checker of scenario A: its node, a :class:`DogObserver` and the
    ``/ball/command`` publisher a person uses (``NODE`` names the node)."""

    NODE = 'check_dog'

    @classmethod
    def setUpClass(cls):
        rospy.init_node(cls.NODE)
        clock()
        cls.dog = DogObserver()
        cls.command = rospy.Publisher('/ball/command', String, queue_size=10)

    def tell_the_ball(self, text):
        wait_for_subscribers(self.command)
        self.command.publish(String(text))

"""The simulator's watch for a second ``/clock`` publisher.

Another node publishing ``/clock`` beside the simulator (``rosbag play
--clock``, a second simulator) makes every node's ROS time jump between two
time lines: C++ nodes abort ("Duration is out of dual 32-bit range"), rospy
timers raise, stamps go back and forth. The package's own nodes follow one
clock and go on (:mod:`exp_assignment2.ros.clock`); the simulator says what
is happening, naming the other publisher, in an ERROR line (again at most
every 10 s while it goes on, with the count of its messages).

The simulator is the clock: it does not listen to its own ``/clock`` (with
``/use_sim_time`` rospy subscribes every node, the simulator too, and at 20x
that was 2000 messages a wall second through a socket and back, a quarter of
the simulator's CPU). :func:`own_clock` sets its ROS time directly instead.
The watch asks the master twice a wall second who publishes ``/clock`` and
subscribes only while someone besides the simulator does, to read the stamps.
"""
import threading

import rosgraph
import rospy
import rospy.impl.simtime
import rospy.rostime
from rosgraph_msgs.msg import Clock

from exp_assignment2.grammar import show_number
from exp_assignment2.refusal import RefusalLog


class SecondClock(object):
    """Reports ``/clock`` messages that ``own`` did not send (no ROS).

    :param own: the caller id of the simulator (its node name)
    :param sim_time: ``sim_time()`` is the simulator's own time (s)
    :param log: ``log(line)``, e.g. rospy.logerr
    """

    def __init__(self, own, sim_time, log, period=10.0):
        self.own, self.sim_time = own, sim_time
        self.report = RefusalLog('/clock', log, period=period, what='messages of other publishers')

    def saw(self, sender, stamp):
        """A ``/clock`` message of ``sender`` stamped ``stamp`` (s)."""
        if sender == self.own:
            return
        self.report('%s publishes it too (its stamp: %s s; the simulator\'s time: %s s): ROS '
                    'time jumps between the two in every node; stop it, or play bags without '
                    '--clock' % (sender or 'a node', show_number(stamp),
                                 show_number(self.sim_time())))


def own_clock():
    """Stop rospy's subscription of this process to ``/clock``; returns
    ``set_time(t)``, which sets this process's ROS time (a rospy.Time), as
    that subscription did with every message."""
    subscriber = getattr(rospy.impl.simtime, '_clock_sub', None)
    if subscriber is not None:
        subscriber.unregister()
        rospy.impl.simtime._clock_sub = None
    return rospy.rostime._set_rostime


def watch_clock(sim_time, period=0.5):
    """Report other publishers of ``/clock``: the master is asked every
    ``period`` wall seconds; the simulator is subscribed to ``/clock`` only
    while another node publishes it."""
    own = rospy.get_name()
    watch = SecondClock(own, sim_time, rospy.logerr)

    def on_clock(msg):
        header = getattr(msg, '_connection_header', None) or {}
        watch.saw(header.get('callerid'), msg.clock.to_sec())

    def poll():
        master, subscriber = rosgraph.Master(own), None
        while not rospy.core.is_shutdown_requested():
            try:
                publishers = dict(master.getSystemState()[0]).get('/clock', [])
            except Exception:       # the master is gone: the launch is ending
                publishers = [own]
            others = [node for node in publishers if node != own]
            if others and subscriber is None:
                subscriber = rospy.Subscriber('/clock', Clock, on_clock, queue_size=1)
            elif not others and subscriber is not None:
                subscriber.unregister()
                subscriber = None
            rospy.rostime.wallsleep(period)
    threading.Thread(target=poll, name='clock_watch', daemon=True).start()
    return watch

"""The simulator's watch for a second ``/clock`` publisher.

Another node publishing ``/clock`` beside the simulator (``rosbag play
--clock``, a second simulator) makes every node's ROS time jump between two
time lines: C++ nodes abort ("Duration is out of dual 32-bit range"), rospy
timers raise, stamps go back and forth. The package's own nodes follow one
clock and go on (:mod:`exp_assignment2.ros.clock`); the simulator says what
is happening, naming the other publisher, in an ERROR line (again at most
every 10 s while it goes on, with the count of its messages).

With ``/use_sim_time`` rospy itself subscribes the simulator to ``/clock``;
this subscriber shares that connection (rospy has one per topic and process),
so watching costs no more messages than rospy already receives.
"""
import rospy
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


def watch_clock(sim_time):
    """Subscribe the simulator to ``/clock`` to report other publishers."""
    watch = SecondClock(rospy.get_name(), sim_time, rospy.logerr)

    def on_clock(msg):
        header = getattr(msg, '_connection_header', None) or {}
        watch.saw(header.get('callerid'), msg.clock.to_sec())
    rospy.Subscriber('/clock', Clock, on_clock, queue_size=1)
    return watch

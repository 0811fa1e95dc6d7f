"""The ROS clock as an :class:`~exp_assignment2.waiting.EventClock`.

With ``/use_sim_time`` the clock ticks on every ``/clock`` message, so a wait
ends on its event or exactly when simulated time passes its deadline, and
pauses with the simulator. Before the first ``/clock`` ROS time is 0: nothing
may compute a deadline then, so :meth:`RosClock.wait_for_time` comes first.

The clock follows one ``/clock`` publisher (see :mod:`exp_assignment2.waiting`):
a second one (``rosbag play --clock`` beside the simulator) is ignored, with
one WARN line naming it; when the followed one jumps (a reset of the
simulation), the clock stands still across the jump and waits keep the time
they had left, with a WARN line at most every 5 s. rospy's own time
(``rospy.Time.now()``, log stamps) still jumps: nothing here waits on it.
"""
import threading

import rospy
from rosgraph_msgs.msg import Clock

from exp_assignment2.grammar import show_number
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.waiting import EventClock


class RosClock(EventClock):
    """ROS time; waits woken by events, by ``/clock`` and by shutdown."""

    def __init__(self):
        self.simulated = bool(rospy.get_param('/use_sim_time', False))
        self._started = threading.Event()
        self._jump_log = RefusalLog('/clock', rospy.logwarn, period=5.0, what='jumps')
        self._told = set()          # publishers whose stamps were said to be ignored
        EventClock.__init__(self, now=rospy.get_time, ticking=self.simulated,
                            on_jump=self._on_jump, on_ignored=self._on_ignored)
        if self.simulated:
            rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=1)
        else:
            self._started.set()
        rospy.on_shutdown(self.shutdown)

    def _on_clock(self, msg):
        header = getattr(msg, '_connection_header', None) or {}
        stamp = msg.clock.to_sec()
        self.tick(stamp, header.get('callerid'))
        # rospy's own /clock subscriber may lag ours by a message: started
        # once both have time, so that no log line carries 0.000000
        if not self._started.is_set() and stamp > 0.0 and rospy.get_time() > 0.0:
            self._started.set()

    def _on_jump(self, before, after, sender):
        way = 'back' if after < before else 'forward'
        self._jump_log('ROS time from %s jumped %s from %s s to %s s; this node\'s waits go on '
                       'from where they were' % (sender, way, show_number(before),
                                                 show_number(after)))

    def _on_ignored(self, sender, stamp):
        if sender not in self._told:
            self._told.add(sender)
            rospy.logwarn('%s: /clock from %s ignored (a stamp of %s s): this node follows '
                          '%s\'s clock', rospy.get_name(), sender, show_number(stamp),
                          self.sender)

    def wait_for_time(self, log_every=10.0):
        """Block (in wall time) until ROS time has started; False on shutdown."""
        while not self._started.wait(log_every):
            if self.is_shutdown() or rospy.is_shutdown():
                return False
            rospy.logwarn('%s: waiting for /clock (is the simulator running?)',
                          rospy.get_name())
        return not self.is_shutdown()

    def shutdown(self):
        EventClock.shutdown(self)
        self._started.set()

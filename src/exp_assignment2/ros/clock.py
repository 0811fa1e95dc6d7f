"""The ROS clock as an :class:`~exp_assignment2.waiting.EventClock`.

With ``/use_sim_time`` the clock ticks on every ``/clock`` message, so a wait
ends on its event or exactly when simulated time passes its deadline, and
pauses with the simulator. Before the first ``/clock`` ROS time is 0: nothing
may compute a deadline then, so :meth:`RosClock.wait_for_time` comes first.
"""
import threading

import rospy
from rosgraph_msgs.msg import Clock

from exp_assignment2.waiting import EventClock


class RosClock(EventClock):
    """ROS time; waits woken by events, by ``/clock`` and by shutdown."""

    def __init__(self):
        self.simulated = bool(rospy.get_param('/use_sim_time', False))
        self._latest = 0.0
        self._started = threading.Event()
        EventClock.__init__(self, now=self._now, ticking=self.simulated)
        if self.simulated:
            rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=1)
        else:
            self._started.set()
        rospy.on_shutdown(self.shutdown)

    def _now(self):
        # our /clock subscriber may run ahead of rospy's own by one message
        return max(rospy.get_time(), self._latest)

    def _on_clock(self, msg):
        self._latest = msg.clock.to_sec()
        if not self._started.is_set() and self._latest > 0.0:
            self._started.set()
        self.tick(self._latest)

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

"""How the launch surface's nodes wait and stop.

roslaunch stops a node with SIGINT (then SIGTERM). rospy's own handler would
shut the node down inside the signal handler, in the middle of whatever
service call was running, and run clean-up (unloading controllers, deleting
a model) there. These nodes start rospy with ``disable_signals=True``
instead: a :class:`Stop` turns the signals into a flag; every wait ends
early when it is raised, and the clean-up runs afterwards in the main
thread, with the node still connected.
"""
import signal
import threading
import time

import rospy

SLICE = 0.5     # s: how soon a wait notices a stop


class Stop(object):
    """SIGINT and SIGTERM as a flag; waits that end when it is raised.

    The handler only sets an attribute: one that took a lock (Event.set)
    could deadlock with the main thread it interrupts inside that lock, so
    waits look at the flag every :data:`SLICE` s instead."""

    def __init__(self):
        self.stopped = False
        for sig in (signal.SIGINT, signal.SIGTERM):
            signal.signal(sig, self._on_signal)

    def _on_signal(self, _sig, _frame):
        self.stopped = True

    def __bool__(self):
        return self.stopped

    def wait(self, event=None, timeout=None):
        """Until ``event`` is set (True), the node is stopped or ``timeout``
        s pass (False); without ``event``, until the node is stopped."""
        event = event or threading.Event()
        deadline = None if timeout is None else time.monotonic() + timeout
        while not self.stopped:
            left = SLICE if deadline is None else min(SLICE, deadline - time.monotonic())
            if left <= 0:
                break
            if event.wait(left):
                return True
        return event.is_set()

    def wait_for_service(self, name, timeout=None):
        """True once ``name`` is served; False when stopped or after ``timeout`` s."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while not self.stopped:
            left = SLICE if deadline is None else min(SLICE, deadline - time.monotonic())
            if left <= 0:
                return False
            try:
                rospy.wait_for_service(name, timeout=max(left, 0.01))
                return True
            except rospy.ROSException:
                continue
        return False

"""Waiting for events with a deadline in the simulator's time (no ROS).

Every wait of the behaviours goes through :meth:`EventClock.wait_until`: the
waiter sleeps on one condition variable and wakes when an event source calls
:meth:`EventClock.notify` (a camera frame, an arrival, a word heard, a goal
finished) or when the clock passes its deadline. With a ticking clock (the
simulator's ``/clock``), the clock's source calls :meth:`EventClock.tick`, which
wakes waiters only once the earliest deadline has passed; with wall time the
waiter sleeps until its deadline. Nothing polls.

Event sources must call :meth:`notify` without holding locks that a waiter's
predicate takes (the predicate runs under the clock's condition).
"""
import heapq
import threading
import time


class EventClock(object):
    """A clock whose waits end on an event, a deadline or shutdown.

    :param now: the time source (s), e.g. ROS time
    :param ticking: True when ``now`` only advances through :meth:`tick`
        (simulated time); False for wall time
    :param wall_guard: longest single sleep (wall s) as a safety net, e.g.
        when a ticking clock stops while the simulator is paused
    """

    def __init__(self, now=time.monotonic, ticking=False, wall_guard=1.0):
        self._now, self.ticking, self.wall_guard = now, ticking, wall_guard
        self.cond = threading.Condition()
        self._deadlines = []
        self._shutdown = False

    def now(self):
        """The current time (s)."""
        return self._now()

    def notify(self):
        """Wake every waiter to look at its predicate again (an event happened)."""
        with self.cond:
            self.cond.notify_all()

    def tick(self, now):
        """The clock advanced to ``now``: wake waiters whose deadline passed."""
        with self.cond:
            if self._deadlines and self._deadlines[0] <= now:
                self.cond.notify_all()

    def shutdown(self):
        """End every wait (the process is stopping)."""
        with self.cond:
            self._shutdown = True
            self.cond.notify_all()

    def is_shutdown(self):
        return self._shutdown

    def wait_until(self, predicate, timeout):
        """Wait until ``predicate()`` is true (True) or ``timeout`` s of this
        clock have passed or the clock shuts down (False)."""
        deadline = self.now() + timeout
        with self.cond:
            heapq.heappush(self._deadlines, deadline)
            try:
                while True:
                    if predicate():
                        return True
                    now = self.now()
                    if self._shutdown or now >= deadline:
                        return False
                    wait = self.wall_guard
                    if not self.ticking:
                        wait = min(wait, deadline - now)
                    self.cond.wait(wait)
            finally:
                self._deadlines.remove(deadline)
                heapq.heapify(self._deadlines)

    def sleep(self, seconds):
        """Sleep ``seconds`` of this clock; False if it shut down meanwhile."""
        self.wait_until(self.is_shutdown, seconds)
        return not self._shutdown

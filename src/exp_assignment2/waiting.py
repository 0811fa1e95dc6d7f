"""Waiting for events with a deadline in the simulator's time (no ROS).

Every wait of the behaviours goes through :meth:`EventClock.wait_until`: the
waiter sleeps on one condition variable and wakes when an event source calls
:meth:`EventClock.notify` (a camera frame, an arrival, a word heard, a goal
finished) or when the clock passes its deadline. With a ticking clock (the
simulator's ``/clock``), the clock's source calls :meth:`EventClock.tick`, which
wakes waiters only once the earliest deadline has passed; with wall time the
waiter sleeps until its deadline. Nothing polls.

A ticking clock never jumps. It follows one sender of ticks (one ``/clock``
publisher); ticks from another are ignored while the one it follows is alive
(ticked within ``SWITCH_AFTER`` wall s), so a second publisher's stamps (``rosbag
play --clock`` beside the simulator, stamps of 0 or 2^32 - 1 s) do not move
it. When the followed source itself jumps (time set back to 0 by a reset, a
bag played in a loop) or another sender takes over, the clock stands still
across the jump and goes on from where it was at the source's pace: every wait
keeps the time it had left and every time a behaviour kept stays comparable
with :meth:`EventClock.now`. Stamps of the source are brought onto this time
line by :meth:`EventClock.from_source`.

Event sources must call :meth:`notify` without holding locks that a waiter's
predicate takes (the predicate runs under the clock's condition).
"""
import heapq
import threading
import time

# A forward step of the source counts as a jump when it is longer than
# FORWARD_JUMP s plus MAX_PACE s for each wall second since the last tick: the
# simulator runs a few times faster than real time, never a hundred.
FORWARD_JUMP = 60.0
MAX_PACE = 100.0
SWITCH_AFTER = 1.0      # wall s of silence of the followed sender before another is followed


class EventClock(object):
    """A clock whose waits end on an event, a deadline or shutdown.

    :param now: the time source (s), e.g. ROS time
    :param ticking: True when ``now`` only advances through :meth:`tick`
        (simulated time); False for wall time
    :param wall_guard: longest single sleep (wall s) as a safety net, e.g.
        when a ticking clock stops while the simulator is paused
    :param on_jump: called as ``on_jump(before, after, sender)`` (source
        times, s) when the source jumps, outside the clock's lock
    :param on_ignored: called as ``on_ignored(sender, stamp)`` for a tick of a
        sender that is not followed, outside the clock's lock
    :param wall: the wall clock that tells a jump from a fast simulator
    """

    def __init__(self, now=time.monotonic, ticking=False, wall_guard=1.0, on_jump=None,
                 on_ignored=None, wall=time.monotonic):
        self._source, self.ticking, self.wall_guard = now, ticking, wall_guard
        self.on_jump, self.on_ignored, self._wall = on_jump, on_ignored, wall
        self.sender = None          # whose ticks this clock follows
        self.cond = threading.Condition()
        self._deadlines = []
        self._shutdown = False
        self._time = None           # this clock's time at the last tick
        self._last = None           # (source time, wall time) of the last tick
        self._offset = 0.0          # this clock's time minus the source's
        self.jumps = 0

    def now(self):
        """The current time (s)."""
        if self.ticking and self._time is not None:
            return self._time
        return self._source()

    def from_source(self, stamp):
        """A time of the source (e.g. a message's stamp) on this clock's time
        line, never later than :meth:`now`."""
        return min(stamp + self._offset, self.now())

    def notify(self):
        """Wake every waiter to look at its predicate again (an event happened)."""
        with self.cond:
            self.cond.notify_all()

    def tick(self, now, sender=None):
        """``sender``'s source advanced to ``now``: wake waiters whose deadline
        passed. A jump of the source (backwards, or forwards faster than any
        simulator runs) does not move this clock; nor does another sender
        while the followed one is alive."""
        wall = self._wall()
        jumped = ignored = False
        with self.cond:
            if self._last is not None and sender != self.sender:
                if wall - self._last[1] < SWITCH_AFTER:
                    ignored = True
                else:
                    jumped = True
            elif self._last is not None:
                step, wall_step = now - self._last[0], max(0.0, wall - self._last[1])
                jumped = step < 0 or step > FORWARD_JUMP + MAX_PACE * wall_step
            if not ignored:
                before = self._last[0] if self._last is not None else None
                if jumped:
                    self.jumps += 1
                    self._offset = self._time - now
                self.sender, self._last = sender, (now, wall)
                # max(): after a jump to 2^32 s the offset is rounded to 1e-6 s
                self._time = now if self._time is None else max(self._time, now + self._offset)
                if self._deadlines and self._deadlines[0] <= self._time:
                    self.cond.notify_all()
        if ignored and self.on_ignored is not None:
            self.on_ignored(sender, now)
        if jumped and self.on_jump is not None:
            self.on_jump(before, now, sender)

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

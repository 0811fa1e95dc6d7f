"""The small interfaces the behaviours are written against.

These classes document the contract; implementations need not inherit from
them. The ROS ones are in ``exp_assignment2.ros``, the fakes in the unit
tests. Times are seconds of the clock's time (ROS time in a running system).
"""


class Clock(object):
    """Time and waiting: :class:`exp_assignment2.waiting.EventClock` is one."""

    def now(self):
        """The current time (s)."""

    def wait_until(self, predicate, timeout):
        """Block until ``predicate()`` holds (True), ``timeout`` s pass or the
        clock shuts down (False). Re-checked whenever :meth:`notify` is called."""

    def sleep(self, seconds):
        """Sleep ``seconds``; False if the clock shut down meanwhile."""

    def notify(self):
        """An event happened: waiters look at their predicates again."""

    def is_shutdown(self):
        """True once the process is stopping."""


class Goal(object):
    """A motion under way that can be waited for and cancelled."""

    def done(self):
        """True once the motion ended (reached, failed or cancelled)."""

    def succeeded(self):
        """True when it ended at its target."""

    def cancel(self):
        """Stop pursuing it (no-op once done)."""


class Log(object):
    """Where the behaviours write their story: ``info`` and ``warn``, each
    ``(fmt, *args)`` like the logging module."""

    def info(self, fmt, *args):
        """An event worth a line."""

    def warn(self, fmt, *args):
        """Something went wrong but the behaviour goes on."""


class DogBody(object):
    """The dog's muscles. Velocities follow REP 103 (+angular turns left)."""

    def drive(self, linear, angular):
        """Move at (linear m/s, angular rad/s) until the next drive() or stop()."""

    def stop(self):
        """Stand still."""

    def head(self, angle):
        """Turn the head to ``angle`` (rad, 0 = straight ahead)."""

    def go_to(self, x, y):
        """Start driving to (x, y) in the arena; returns a :class:`Goal`."""


class DogEyes(object):
    """The dog's camera and ball detector."""

    def last_seen(self):
        """Time of the latest frame that showed the ball, or None."""

    def follow(self, servo):
        """Call ``servo(ball, width)`` on every frame (None stops); ``ball`` is a
        :class:`exp_assignment2.vision.Ball` or None. Each frame also notifies
        the clock."""


class MiroBody(object):
    """MiRo's motion: orders for the grounding and motion-controller nodes."""

    def go(self, command):
        """Order ``go_home``, ``go_rand`` or ``go to X Y``; returns a :class:`Goal`
        that is done when MiRo arrives (a later order abandons it)."""

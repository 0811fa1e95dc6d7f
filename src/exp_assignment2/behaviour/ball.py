"""Who moves the ball in scenario A (no ROS).

* :class:`BallRoutine` (``move_ball_around``): the original's routine: a
  random goal, wait, another, wait, disappear under the ground, wait, again.
  It pauses while a person moves the ball (:meth:`BallRoutine.set_enabled`).
* :class:`BallCommands` (``human_commands``): a person's ``/ball/command``
  text (``go to X Y``, ``hide``, ``show``, ``auto``, ``stop``) into ball goals;
  any command but ``auto`` pauses the routine until ``auto``.

``ball.go_to(x, y, z)`` starts a ball goal (z is the height: ``arena.BALL_GROUND_Z``
rests it on the ground, below 0 hides it) and returns a Goal.
"""
from exp_assignment2 import arena
from exp_assignment2.grammar import parse_ball_command
from exp_assignment2.refusal import parse_or_refuse

HIDE_Z = -1.0     # under the ground: out of every camera's view


class BallRoutine(object):
    """The automatic ball mover; every duration in the clock's time."""

    def __init__(self, clock, ball, rng, log, wait_time=8.0, hidden_time=10.0,
                 moves_per_round=2, goal_timeout=60.0, enabled=True):
        self.clock, self.ball, self.rng, self.log = clock, ball, rng, log
        self.wait_time, self.hidden_time = wait_time, hidden_time
        self.moves_per_round, self.goal_timeout = int(moves_per_round), goal_timeout
        self.enabled, self.goal = enabled, None

    def set_enabled(self, enabled):
        """Resume (True) or pause (False, cancelling the goal under way)."""
        if enabled == self.enabled:
            return
        self.enabled = enabled
        self.log.info('move_ball_around: %s', 'resumed' if enabled else
                      'paused (a person moves the ball)')
        if not enabled and self.goal is not None:
            self.goal.cancel()
        self.clock.notify()

    def _move(self, x, y, z):
        self.goal = goal = self.ball.go_to(x, y, z)
        if not self.clock.wait_until(lambda: goal.done() or not self.enabled,
                                     self.goal_timeout):
            goal.cancel()
            if self.clock.is_shutdown():
                return False
            self.log.warn('move_ball_around: (%.1f, %.1f) not reached within %.0f s',
                          x, y, self.goal_timeout)
        return self._going()

    def _wait(self, seconds):
        self.clock.wait_until(lambda: not self.enabled, seconds)
        return self._going()

    def _going(self):
        return self.enabled and not self.clock.is_shutdown()

    def round(self):
        """One round: the moves, then the disappearance; stops early when paused."""
        for _ in range(self.moves_per_round):
            x, y = arena.random_point(self.rng)
            self.log.info('move_ball_around: ball to (%.1f, %.1f)', x, y)
            if not (self._move(x, y, arena.BALL_GROUND_Z) and self._wait(self.wait_time)):
                return
        self.log.info('move_ball_around: ball disappears')
        x, y = arena.random_point(self.rng)
        if self._move(x, y, HIDE_Z):
            self._wait(self.hidden_time)

    def run(self):
        """Rounds until the clock shuts down (waiting while paused)."""
        while not self.clock.is_shutdown():
            if self.clock.wait_until(lambda: self.enabled, 60.0):
                self.round()


class BallCommands(object):
    """Turns a person's text into ball goals.

    :param auto: ``auto(flag)`` resumes (True) or pauses (False) the routine
    :param position: ``position()`` is the ball's (x, y), or None if unknown
    :param refuse: called with the reason for a refused command (one log line)
    """

    def __init__(self, ball, auto, position, refuse, log):
        self.ball, self.auto, self.position = ball, auto, position
        self.refuse, self.log = refuse, log
        self.goal = None

    def handle(self, text):
        """Act on one command; returns what was done, or None when refused."""
        cmd = parse_or_refuse(parse_ball_command, text, self.refuse)
        if cmd is None:
            return None
        self.log.info('/ball/command: %s', cmd.kind if cmd.kind != 'go_to'
                      else 'go to %g %g' % (cmd.x, cmd.y))
        if cmd.kind == 'auto':
            self.auto(True)
            return 'auto'
        self.auto(False)
        if cmd.kind == 'stop':
            if self.goal is not None:
                self.goal.cancel()
            return 'stop'
        if cmd.kind == 'go_to':
            self.goal = self.ball.go_to(cmd.x, cmd.y, arena.BALL_GROUND_Z)
            return 'go_to'
        where = self.position()
        if where is None:
            self.refuse('%s: the ball\'s position is not known yet (no /ball/odom)' % cmd.kind)
            return None
        x, y = (max(-arena.GOAL_LIMIT, min(arena.GOAL_LIMIT, v)) for v in where)
        self.goal = self.ball.go_to(x, y, HIDE_Z if cmd.kind == 'hide' else arena.BALL_GROUND_Z)
        return cmd.kind

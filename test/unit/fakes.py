"""Fakes for the behaviours' interfaces: a hand-turned clock and toy worlds.

The clock advances only inside waits, in fixed steps, ticking the world
after each one; a whole state machine run takes milliseconds and is exactly
repeatable. The dog's world has a robot that drives (diff drive, ideal), a
ball and a camera that sees the ball geometrically (80 deg field of view,
800 px wide), so the real servo and the real states act on it.
"""
import math

from exp_assignment2.geometry import normalize_angle
from exp_assignment2.vision import Ball


class Shutdown(Exception):
    """Raised by the fake clock when a test's time budget is spent."""


class FakeClock(object):
    """A clock turned by the waits themselves, ``step`` s at a time."""

    def __init__(self, step=0.05, limit=10000.0):
        self.t, self.step, self.limit = 0.0, step, limit
        self.tickers = []
        self.shut = False
        self.notified = 0

    def now(self):
        return self.t

    def notify(self):
        self.notified += 1

    def is_shutdown(self):
        return self.shut

    def advance(self, dt):
        self.t += dt
        if self.t > self.limit:
            raise Shutdown('fake time limit %.0f s reached' % self.limit)
        for tick in list(self.tickers):
            tick(self.t, dt)

    def wait_until(self, predicate, timeout):
        end = self.t + timeout
        while True:
            if predicate():
                return True
            if self.shut or self.t >= end:
                return False
            # at least a microsecond: a deadline a rounding error ahead still passes
            self.advance(max(min(self.step, end - self.t), 1e-6))

    def sleep(self, seconds):
        self.wait_until(lambda: self.shut, seconds)
        return not self.shut


class FakeGoal(object):
    def __init__(self, world, x, y):
        self.world, self.target = world, (x, y)
        self.state = 'active'          # active, succeeded, cancelled, failed

    def done(self):
        return self.state != 'active'

    def succeeded(self):
        return self.state == 'succeeded'

    def cancel(self):
        if self.state == 'active':
            self.state = 'cancelled'


def step_towards(body, goal, speed, dt, tolerance):
    """Move ``body`` (x, y attributes) straight at ``goal``'s target; the goal
    succeeds within ``tolerance``. Returns the heading taken, or None."""
    dx, dy = goal.target[0] - body.x, goal.target[1] - body.y
    dist = math.hypot(dx, dy)
    step = min(dist, speed * dt)
    heading = None
    if dist > 0:
        body.x += dx / dist * step
        body.y += dy / dist * step
        heading = math.atan2(dy, dx)
    if dist - step < tolerance:
        goal.state = 'succeeded'
    return heading


class RecordingLog(object):
    """A log that keeps its (level, text) lines (rospy's or the engine's calls)."""

    def __init__(self):
        self.lines = []

    def _add(self, level, fmt, args):
        self.lines.append((level, fmt % args if args else fmt))

    def info(self, fmt, *args):
        self._add('info', fmt, args)

    def warn(self, fmt, *args):
        self._add('warn', fmt, args)

    def error(self, fmt, *args):
        self._add('error', fmt, args)

    def text(self):
        return '\n'.join(line for _, line in self.lines)


class DogWorld(object):
    """A robot, a ball and a camera, ticking with the fake clock; it is both
    the body and the eyes of :class:`exp_assignment2.behaviour.dog.Dog`."""

    WIDTH, HFOV, FRAME_PERIOD = 800, math.radians(80), 0.05

    def __init__(self, clock, robot=(-5.0, 7.0, math.pi), ball=(-7.0, 6.0), goal_speed=1.0):
        self.clock = clock
        self.x, self.y, self.yaw = robot
        self.ball, self.ball_visible = ball, True
        self.cmd = (0.0, 0.0)
        self.head_angle, self.head_log = 0.0, []
        self.goals, self.goal_speed, self.goal_stuck = [], goal_speed, False
        self.servo, self.seen_at, self.frames = None, None, 0
        self.next_frame = 0.0
        clock.tickers.append(self.tick)

    # body
    def drive(self, linear, angular):
        self.cmd = (linear, angular)

    def stop(self):
        self.cmd = (0.0, 0.0)

    def head(self, angle):
        self.head_angle = angle
        self.head_log.append((self.clock.now(), angle))

    def go_to(self, x, y):
        goal = FakeGoal(self, x, y)
        self.goals.append(goal)
        return goal

    # eyes
    def last_seen(self):
        return self.seen_at

    def follow(self, servo):
        self.servo = servo

    def sighting(self):
        """The ball as the camera sees it now, or None."""
        if not self.ball_visible:
            return None
        dx, dy = self.ball[0] - self.x, self.ball[1] - self.y
        dist = math.hypot(dx, dy)
        bearing = normalize_angle(math.atan2(dy, dx) - self.yaw - self.head_angle)
        if dist < 0.6 or abs(bearing) > self.HFOV / 2:
            return None
        f = self.WIDTH / (2 * math.tan(self.HFOV / 2))
        cx = self.WIDTH / 2 - f * math.tan(bearing)
        radius = f * 0.5 / dist
        if radius <= 10:
            return None
        return Ball(cx, self.WIDTH / 2, radius, cx, self.WIDTH / 2)

    def distance_to_ball(self):
        return math.hypot(self.ball[0] - self.x, self.ball[1] - self.y)

    # time passes
    def tick(self, now, dt):
        active = [g for g in self.goals if not g.done()]
        if active and not self.goal_stuck:
            heading = step_towards(self, active[-1], self.goal_speed, dt, 0.1)
            if heading is not None:
                self.yaw = heading
        else:
            v, w = self.cmd
            self.yaw = normalize_angle(self.yaw + w * dt)
            self.x += v * math.cos(self.yaw) * dt
            self.y += v * math.sin(self.yaw) * dt
        if now + 1e-9 >= self.next_frame:
            self.next_frame += self.FRAME_PERIOD
            ball = self.sighting()
            if ball is not None:
                self.seen_at = now
            self.frames += 1
            if self.servo is not None:
                self.servo(ball, self.WIDTH)
            self.clock.notify()


class MiroWorld(object):
    """MiRo on the grid with ideal motion at ``speed`` m/s; it grounds the
    commands itself, as the grounding node would. Body of the MiRo states."""

    def __init__(self, clock, rng, home=(3, 3), speed=1.0):
        self.clock, self.rng, self.home, self.speed = clock, rng, home, speed
        self.x = self.y = 0.0
        self.goals, self.commands = [], []
        clock.tickers.append(self.tick)

    def go(self, command):
        from exp_assignment2.grounding import ground
        for goal in self.goals:
            if not goal.done():
                goal.state = 'abandoned'     # the controller is retargeted
        goal = FakeGoal(self, *ground(command, self.home, self.rng))
        self.goals.append(goal)
        self.commands.append((self.clock.now(), command, goal.target))
        return goal

    def tick(self, now, dt):
        active = [g for g in self.goals if not g.done()]
        if not active:
            return
        step_towards(self, active[-1], self.speed, dt, 0.05)
        if active[-1].succeeded():
            self.clock.notify()

    def arrivals(self):
        return [g.target for g in self.goals if g.succeeded()]

"""Control laws as plain functions and classes (no ROS).

* :class:`GoToPoint`: the originals' go-to-point for a diff-drive robot: turn
  towards the goal, then drive while correcting the heading (REP 103: +z turns
  left; the ROS layer flips the sign for a robot wired the other way).
* :func:`planar_velocity`: the ball's (and MiRo's) go-to-point, holonomic.
* :func:`visual_servo` and :class:`BallFollower`: the ball follower: turn rate
  proportional to the ball's horizontal offset, forward speed proportional to
  the apparent-radius error, both normalised by image width.
"""
import math
from collections import namedtuple

from exp_assignment2.geometry import cap_norm, clamp, normalize_angle

FIX_YAW, GO_STRAIGHT, DONE = 'fix_yaw', 'go_straight', 'done'

Command = namedtuple('Command', 'linear angular')


class GoToPoint(object):
    """Turn-then-drive controller; :meth:`update` gives a velocity and phase.

    Gains and tolerances default to the original's values.
    """

    def __init__(self, yaw_precision=math.pi / 9, yaw_precision_fine=math.pi / 90,
                 dist_precision=0.1, kp_a=3.0, kp_d=0.2, max_angular=0.6, max_linear=0.6,
                 min_linear=0.1):
        self.yaw_precision = yaw_precision
        self.yaw_precision_fine = yaw_precision_fine
        self.dist_precision = dist_precision
        self.kp_a, self.kp_d = kp_a, kp_d
        self.max_angular, self.max_linear = max_angular, max_linear
        self.min_linear = min_linear   # no crawling at the end of the approach
        self.phase = FIX_YAW

    def reset(self):
        self.phase = FIX_YAW

    def update(self, x, y, yaw, goal_x, goal_y):
        """Return (Command, phase) for the robot at (x, y, yaw)."""
        dx, dy = goal_x - x, goal_y - y
        dist = math.hypot(dx, dy)
        err = normalize_angle(math.atan2(dy, dx) - yaw)
        if self.phase != DONE and dist <= self.dist_precision:
            self.phase = DONE
        if self.phase == FIX_YAW:
            if abs(err) > self.yaw_precision_fine:
                return Command(0.0, clamp(self.kp_a * err, self.max_angular)), FIX_YAW
            self.phase = GO_STRAIGHT
        if self.phase == GO_STRAIGHT:
            if abs(err) > self.yaw_precision:
                self.phase = FIX_YAW
                return Command(0.0, clamp(self.kp_a * err, self.max_angular)), FIX_YAW
            return (Command(clamp(max(self.kp_d * dist, self.min_linear), self.max_linear),
                            clamp(self.kp_a * err, self.max_angular)), GO_STRAIGHT)
        return Command(0.0, 0.0), DONE


def planar_velocity(x, y, goal_x, goal_y, kp=0.5, max_speed=2.0):
    """Holonomic go-to-point: (vx, vy) towards the goal, speed capped."""
    return cap_norm(kp * (goal_x - x), kp * (goal_y - y), max_speed)


def visual_servo(ball_x, ball_radius, width, target_radius_ratio=0.25,
                 k_angular=1.6, k_linear=8.0, max_angular=1.0, max_linear=0.8):
    """Velocity that brings the ball to the image centre at the target size.

    The original used 0.002 rad/s per px and 0.01 m/s per px at 800 px; here
    the gains act on offsets normalised by the image width (x 800). A ball to
    the right of centre turns the robot right (negative z, REP 103).
    """
    offset = (ball_x - width / 2.0) / width
    radius_error = ball_radius / width - target_radius_ratio
    return Command(clamp(-k_linear * radius_error, max_linear),
                   clamp(-k_angular * offset, max_angular))


class BallFollower(object):
    """The visual servo on detections: a ball in, a command out; with no ball
    it turns in place to search, as the original did."""

    def __init__(self, target_radius_ratio=0.3, max_linear=0.8, max_angular=1.0,
                 search_rate=0.5):
        self.target_radius_ratio = target_radius_ratio
        self.max_linear, self.max_angular = max_linear, max_angular
        self.search_rate = search_rate

    def command(self, ball, width):
        """The :class:`Command` for a :class:`~exp_assignment2.vision.Ball` (or None)."""
        if ball is None:
            return Command(0.0, self.search_rate)
        return visual_servo(ball.cx, ball.radius, width, self.target_radius_ratio,
                            max_angular=self.max_angular, max_linear=self.max_linear)

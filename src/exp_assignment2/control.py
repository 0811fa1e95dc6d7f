"""Control laws as plain functions and classes (no ROS).

* :class:`GoToPoint`: the originals' go-to-point for a diff-drive robot: turn
  towards the goal, then drive while correcting the heading (REP 103: +z turns
  left).
* :func:`planar_velocity`: the ball's (and MiRo's) go-to-point, holonomic.
* :func:`visual_servo`: the ball follower: turn rate proportional to the
  ball's horizontal offset, forward speed proportional to the apparent-radius
  error, both normalised by image width.
"""
import math
from collections import namedtuple

FIX_YAW, GO_STRAIGHT, DONE = 'fix_yaw', 'go_straight', 'done'

# The original's feedback wording (kept: existing clients may match on it).
FEEDBACK = {FIX_YAW: 'Fixing the yaw', GO_STRAIGHT: 'Reaching the goal',
            DONE: 'Target reached!'}
ANGLE_ALIGNED = 'Angle aligned'

Command = namedtuple('Command', 'linear angular')


def normalize_angle(angle):
    """Wrap an angle to [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def clamp(value, limit):
    return max(-limit, min(limit, value))


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
    dx, dy = goal_x - x, goal_y - y
    vx, vy = kp * dx, kp * dy
    speed = math.hypot(vx, vy)
    if speed > max_speed:
        vx, vy = vx * max_speed / speed, vy * max_speed / speed
    return vx, vy


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

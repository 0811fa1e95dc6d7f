"""The PlanningAction's goals: wording, checks and construction.

The feedback strings are the original's, word for word (clients may match on
them). Goal checks are the same for both servers: x and y must be finite and
inside the arena; the orientation and the header are ignored, whatever their
values; z is the ball's height for ``/reaching_goal`` (finite, at most
``arena.BALL_MAX_Z``) and ignored by ``/robot_reaching_goal``.
"""
import math

from exp_assignment2 import arena
from exp_assignment2.control import DONE, FIX_YAW, GO_STRAIGHT, planar_velocity
from exp_assignment2.grammar import show_number, show_numbers

FIXING_YAW = 'Fixing the yaw'
ANGLE_ALIGNED = 'Angle aligned'
REACHING = 'Reaching the goal'
REACHED = 'Target reached!'


def goal_error(x, y, z=None):
    """Why a goal at (x, y[, z]) cannot be executed, or None when it can.

    Pass ``z`` only where it is used (the ball's height). Numbers are printed
    by :func:`~exp_assignment2.grammar.show_number` (1e+308, not 309 digits)."""
    try:
        if not (math.isfinite(x) and math.isfinite(y)):
            return 'goal x, y = %s is not finite' % show_numbers((x, y))
        if z is not None and not math.isfinite(z):
            return 'goal z = %s (the ball\'s height) is not finite' % show_number(z)
    except TypeError:
        return 'goal position is not numeric'
    if not arena.in_arena(x, y):
        return ('goal x, y = %s is outside the arena: x and y must be in [-%g, %g]'
                % (show_numbers((x, y)), arena.GOAL_LIMIT, arena.GOAL_LIMIT))
    if z is not None and z > arena.BALL_MAX_Z:
        return ('goal z = %s is above the %g m the ball may rise to'
                % (show_number(z), arena.BALL_MAX_Z))
    return None


def make_goal(x, y, z=0.0, stamp=None):
    """An ``exp_assignment2/PlanningGoal`` for (x, y, z) in the odom frame.

    The message class is imported here, not at module level, so that the rest
    of this module is usable without a catkin build."""
    from exp_assignment2.msg import PlanningGoal
    goal = PlanningGoal()
    goal.target_pose.header.frame_id = 'odom'
    if stamp is not None:
        goal.target_pose.header.stamp = stamp
    pos = goal.target_pose.pose.position
    pos.x, pos.y, pos.z = float(x), float(y), float(z)
    goal.target_pose.pose.orientation.w = 1.0
    return goal


class RobotGoalController(object):
    """``/robot_reaching_goal``: turn towards the goal, then drive (the
    originals' go_to_point). Feedback: 'Fixing the yaw', 'Angle aligned' once
    the heading is right, 'Reaching the goal', 'Target reached!'."""

    def __init__(self, go_to_point):
        self.ctrl = go_to_point
        self.phase = None

    def begin(self):
        self.ctrl.reset()
        self.phase = None

    def step(self, x, y, yaw, goal_x, goal_y):
        """((linear, angular), [feedback texts], done) for the robot's pose."""
        cmd, phase = self.ctrl.update(x, y, yaw, goal_x, goal_y)
        if phase == DONE:
            return (0.0, 0.0), [REACHED], True
        texts = [ANGLE_ALIGNED] if phase == GO_STRAIGHT and self.phase != GO_STRAIGHT else []
        self.phase = phase
        texts.append(FIXING_YAW if phase == FIX_YAW else REACHING)
        return (cmd.linear, cmd.angular), texts, False


class BallGoalController(object):
    """``/reaching_goal``: straight to (x, y) at a capped speed."""

    def __init__(self, kp=0.5, max_speed=2.0, precision=0.1):
        self.kp, self.max_speed, self.precision = kp, max_speed, precision

    def begin(self):
        pass

    def step(self, x, y, goal_x, goal_y):
        """((vx, vy), [feedback texts], done) for the ball at (x, y)."""
        if math.hypot(goal_x - x, goal_y - y) <= self.precision:
            return (0.0, 0.0), [REACHED], True
        return planar_velocity(x, y, goal_x, goal_y, self.kp, self.max_speed), [REACHING], False

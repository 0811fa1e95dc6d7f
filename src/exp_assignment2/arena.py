"""Scenario A's arena, as plain data: where goals may be, the kennel, the person.

The walls' inner faces are at +-9.3 m (``urdf/arena.urdf``); goals live in
the square x, y in [-8, 8].
"""
import math

GOAL_LIMIT = 8.0                # goals live in x, y in [-8, 8]
WALL_INNER = 9.3                # inner faces of the wall ring
KENNEL = (7.0, 7.0)             # the dog's home
PERSON = (-7.0, 7.0)            # the seated human figure
ROBOT_SPAWN = (-5.0, 7.0, math.pi)
BALL_SPAWN = (-7.0, 6.0)
BALL_RADIUS = 0.5
BALL_GROUND_Z = BALL_RADIUS     # a ball at this height rests on the ground
BALL_MAX_Z = 50.0               # highest accepted ball goal (the original lifts it to 20)


def in_arena(x, y, limit=GOAL_LIMIT):
    """True when (x, y) is a finite point inside the goal square."""
    return (math.isfinite(x) and math.isfinite(y)
            and -limit <= x <= limit and -limit <= y <= limit)


def random_point(rng, limit=GOAL_LIMIT):
    """A uniformly random goal (x, y) in the square, from ``rng`` (random.Random)."""
    return rng.uniform(-limit, limit), rng.uniform(-limit, limit)

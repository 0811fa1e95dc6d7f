"""Scenario B's world, as plain data: MiRo's 10 x 10 m grid of whole-number points."""
import math

GRID_MIN, GRID_MAX = 0, 10
HOME = (3, 3)                   # MiRo's home (the /home_posx, /home_posy defaults)
PERSON = (5, 5)                 # where the person is when no gesture told otherwise
RANDOM_MAX = 9                  # go_rand draws 0..9, as the original did


def on_grid(x, y):
    """True when (x, y) is a finite point of the grid's square."""
    try:
        return (math.isfinite(x) and math.isfinite(y)
                and GRID_MIN <= x <= GRID_MAX and GRID_MIN <= y <= GRID_MAX)
    except TypeError:
        return False


def target_point(data):
    """A ``/target_pos``'s data as the grid point (x, y), or None when it is
    not one (the motion controller drives only to those)."""
    return (data[0], data[1]) if len(data) == 2 and on_grid(data[0], data[1]) else None


def random_point(rng):
    """A random grid point for ``go_rand``, from ``rng`` (random.Random)."""
    return rng.randint(GRID_MIN, RANDOM_MAX), rng.randint(GRID_MIN, RANDOM_MAX)

"""Geometry grounding of scenario B: a motion command becomes a grid point (no ROS)."""
from exp_assignment2 import grid
from exp_assignment2.grammar import parse_motion_command


def ground(text, home, rng):
    """Grid point (x, y) for ``go_home``, ``go_rand`` or ``go to X Y``.

    ``go_rand`` draws x, y in 0..9 as the original did; raises
    :class:`~exp_assignment2.grammar.CommandError` for anything else.
    """
    cmd = parse_motion_command(text)
    if cmd.kind == 'go_home':
        return int(home[0]), int(home[1])
    if cmd.kind == 'go_rand':
        return grid.random_point(rng)
    return cmd.x, cmd.y

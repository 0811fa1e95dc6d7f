"""Geometry grounding of scenario B: a motion command becomes a grid point."""
from exp_assignment2.commands import parse_motion_command
from exp_assignment2.world import GRID_MIN


def ground(text, home, rng):
    """Grid point (x, y) for ``go_home``, ``go_rand`` or ``go to X Y``.

    ``go_rand`` draws x, y in 0..9 as the original did; raises
    :class:`~exp_assignment2.commands.CommandError` for anything else.
    """
    cmd = parse_motion_command(text)
    if cmd.kind == 'go_home':
        return int(home[0]), int(home[1])
    if cmd.kind == 'go_rand':
        return rng.randrange(GRID_MIN, 10), rng.randrange(GRID_MIN, 10)
    return cmd.x, cmd.y

"""Places for the ball in an arena (no ROS): inside its box with a margin,
clear of the world's fixed objects, and reached in a straight line that
touches none of them. :mod:`.ball_script` draws its course's places here.

``o`` is the script's options (:class:`~.ball_script.Options`: the ball's
``radius``, the ``margin`` from the arena's edges, the ``clearance`` from a
fixed object); ``rng`` a ``random.Random``.
"""
import math
from collections import namedtuple

STEP = (3.0, 8.0)           # m between consecutive places
TRIES = 2000                # candidate places before giving up on an arena

Arena = namedtuple('Arena', 'x_min x_max y_min y_max obstacles')
Arena.__doc__ = """Where the ball's centre may go: a box, and ``obstacles`` the
world's fixed objects as (x_min, x_max, y_min, y_max) footprints to keep away from."""
Arena.__new__.__defaults__ = ((),)


class ScriptError(ValueError):
    """A ball script that cannot be played (here: an arena with no room for
    the ball); the message is one line saying why."""


def _room(arena, o):
    """(x_min, x_max, y_min, y_max) for places: the arena less the margin."""
    room = (arena.x_min + o.margin, arena.x_max - o.margin,
            arena.y_min + o.margin, arena.y_max - o.margin)
    if not (room[0] < room[1] and room[2] < room[3]):
        raise ScriptError('ball script: the arena x %g..%g, y %g..%g leaves no room for the '
                          'ball %g m from its edges' % (arena.x_min, arena.x_max, arena.y_min,
                                                        arena.y_max, o.margin))
    return room


def _gap(point, box):
    """Distance (m) from a point to a footprint (0 inside it)."""
    x, y = point
    dx = max(box[0] - x, 0.0, x - box[1])
    dy = max(box[2] - y, 0.0, y - box[3])
    return math.hypot(dx, dy)


def _clear(place, arena, o, room):
    return (room[0] <= place[0] <= room[1] and room[2] <= place[1] <= room[3]
            and all(_gap(place, box) >= o.radius + o.clearance for box in arena.obstacles))


def _path_clear(a, b, arena, o):
    """The ball rolling from ``a`` to ``b`` touches no fixed object."""
    n = max(1, int(math.hypot(b[0] - a[0], b[1] - a[1]) / 0.2))
    return all(_gap((a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n), box)
               >= o.radius for i in range(n + 1) for box in arena.obstacles)


def free_place(rng, arena, o):
    """A place anywhere in the arena clear of its fixed objects."""
    room = _room(arena, o)
    for _ in range(TRIES):
        place = (round(rng.uniform(room[0], room[1]), 2), round(rng.uniform(room[2], room[3]), 2))
        if _clear(place, arena, o, room):
            return place
    raise ScriptError('ball script: no place in the arena x %g..%g, y %g..%g is %g m clear '
                      'of its fixed objects' % (arena.x_min, arena.x_max, arena.y_min,
                                                arena.y_max, o.radius + o.clearance))


def next_place(rng, arena, o, here, scale):
    """A place :data:`STEP` m from ``here`` (less in a short run: ``scale``)
    reached in a straight line; any free place when none is."""
    room = _room(arena, o)
    far = max(2.0, STEP[1] * scale)
    near = min(STEP[0], far / 2.0)
    for _ in range(TRIES):
        angle, reach = rng.uniform(-math.pi, math.pi), rng.uniform(near, far)
        place = (round(here[0] + reach * math.cos(angle), 2),
                 round(here[1] + reach * math.sin(angle), 2))
        if _clear(place, arena, o, room) and _path_clear(here, place, arena, o):
            return place
    return free_place(rng, arena, o)

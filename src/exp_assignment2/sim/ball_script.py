"""A person's course for the ball, the same in every run of a seed (no ROS,
no pybullet): what the simulator plays in place of a student's ball node.

In the dog assignment the student's own "person" node moves the ball, so
every submission's dog meets a different ball (random, scripted, or none at
all). A grader can instead have the simulator play a script, a list of legs:

* ``{"hide": S}``: under the floor (z = :data:`HIDDEN_Z`, the assignment's
  way to make it disappear) for S s, where it is (before it was ever shown:
  under the place it first appears at);
* ``{"show": [x, y], "stay": S}``: appears at (x, y), resting on the ground,
  and stays S s;
* ``{"move": [x, y], "speed": V, "stay": S}``: rolls in a straight line to
  (x, y) at V m/s, then stays S s (``stay`` defaults to 0).

:func:`make_script` writes one from a seed (``random.Random(seed)``, no
global state) so that each of the dog's behaviours gets its occasion within
the run: hidden at first (the dog wanders, may sleep), shown, walked to
several places with stops long enough for the head's sweep, hidden long
enough for the dog to give up, then shown and walked again.
:func:`from_legs` checks legs given by hand; :func:`play` says where the ball
is at a script time (s since the script started).
"""
import bisect
import json
import math
import random
from collections import namedtuple

from exp_assignment2.sim import ball_places

Arena, ScriptError = ball_places.Arena, ball_places.ScriptError     # this module's words too

HIDDEN_Z = -3.0             # m: under the floor, as the assignment hides the ball
DEFAULT_DURATION = 200.0    # s: the dog profile's run; the seeded times scale below it
START_HIDE = (20.0, 30.0)   # s hidden at first: the dog wanders, may sleep
STAY = (8.0, 10.0)          # s at rest at a place: the dog's head turns both ways
HIDE = (20.0, 30.0)         # s hidden later: the dog gives up, back to its normal life
SPEED = (0.35, 0.6)         # m/s: a person walking the ball, slower than the dog (0.8)
MOVES = (2, 3)              # moves after each appearance

Options = namedtuple('Options', 'duration ground_z radius margin clearance')
Options.__doc__ = """``duration`` s to fill (default 200), the ball's height when
shown (``ground_z``: resting on the floor), its ``radius``, the ``margin`` (m)
kept from the arena's edges and the ``clearance`` (m) between the ball and a
fixed object."""
DEFAULTS = Options(DEFAULT_DURATION, 0.5, 0.5, 1.0, 1.0)

Leg = namedtuple('Leg', 'kind place speed stay')
Leg.__doc__ = """One leg: ``kind`` hide, show or move; ``place`` (x, y) or None;
``speed`` (m/s, a move's); ``stay`` s (hidden for a hide, at rest afterwards else)."""

Segment = namedtuple('Segment', 't0 t1 x0 y0 x1 y1 hidden')
Script = namedtuple('Script', 'legs segments starts seed duration ground_z')
Script.__doc__ = """A checked course: its legs, the timeline :func:`play` reads, the
seed it came from (None: given by hand), the duration it fills and the ball's height."""

BallPose = namedtuple('BallPose', 'x y z hidden vx vy')
BallPose.__doc__ = """Where the ball is: its centre, whether it is hidden under the
floor, and its velocity in the world (m/s)."""


def options(given=None):
    """:data:`DEFAULTS` with ``given`` (a dict or :class:`Options`) over them."""
    if given is None:
        return DEFAULTS
    if isinstance(given, Options):
        return given
    unknown = sorted(set(given) - set(Options._fields))
    if unknown:
        raise ScriptError('ball script: unknown option %s (known: %s)'
                          % (', '.join(unknown), ', '.join(Options._fields)))
    out = DEFAULTS._replace(**given)
    if not _finite(out.duration) or out.duration <= 0:
        raise ScriptError('ball script: the duration must be a positive number of seconds, '
                          'got %r' % (out.duration,))
    return out


def _finite(value):
    return (isinstance(value, (int, float)) and not isinstance(value, bool)
            and math.isfinite(value))


# the seeded course
def make_script(seed, arena, given=None):
    """The course of ``seed`` (a whole number) in ``arena``: the same legs for
    the same seed, arena and options everywhere. Stays and hides last as the
    dog needs (:data:`STAY`, :data:`HIDE`) in a run of :data:`DEFAULT_DURATION`
    s or more, and shrink in proportion in a shorter one; appearances and
    hides take turns until the duration is filled."""
    if not isinstance(seed, int) or isinstance(seed, bool):
        raise ScriptError('ball script: the seed must be a whole number, got %r' % (seed,))
    o = options(given)
    rng = random.Random(seed)
    scale = min(1.0, o.duration / DEFAULT_DURATION)

    def span(limits):
        return round(rng.uniform(*limits) * scale, 2)
    legs = [Leg('hide', None, None, span(START_HIDE))]
    t = legs[0].stay
    while t < o.duration:
        here = ball_places.free_place(rng, arena, o)
        legs.append(Leg('show', here, None, span(STAY)))
        t += legs[-1].stay
        for _ in range(rng.randint(*MOVES)):
            if t >= o.duration:
                break
            there = ball_places.next_place(rng, arena, o, here, scale)
            speed = round(rng.uniform(*SPEED), 2)
            legs.append(Leg('move', there, speed, span(STAY)))
            t += math.hypot(there[0] - here[0], there[1] - here[1]) / speed + legs[-1].stay
            here = there
        if t < o.duration:
            legs.append(Leg('hide', None, None, span(HIDE)))
            t += legs[-1].stay
    return _compile(legs, o, seed)


# legs given by hand
def parse_legs(legs, arena=None):
    """Legs as JSON gives them (a list of dicts) as :class:`Leg`; a bad leg
    is a :class:`ScriptError` naming it (its number from 1) and what is wrong:
    not a finite number, a place outside ``arena`` (when given), a negative
    time, a move while the ball is hidden."""
    if not isinstance(legs, (list, tuple)) or not legs:
        raise ScriptError('ball script: legs must be a non-empty list, got %s' % _shown(legs))
    out, shown = [], False
    for number, leg in enumerate(legs, 1):
        try:
            out.append(_parse_leg(leg, arena))
            if out[-1].kind == 'move' and not shown:
                raise ScriptError('a move starts where the ball is shown: show it first')
        except ScriptError as exc:
            raise ScriptError('ball script: leg %d %s: %s' % (number, _shown(leg), exc))
        shown = out[-1].kind != 'hide'
    return out


KINDS = {'hide': (), 'show': ('stay',), 'move': ('speed', 'stay')}


def _parse_leg(leg, arena):
    if not isinstance(leg, dict):
        raise ScriptError('a leg is {"hide": S}, {"show": [x, y], "stay": S} or '
                          '{"move": [x, y], "speed": V, "stay": S}')
    kinds = [k for k in KINDS if k in leg]
    if len(kinds) != 1:
        raise ScriptError('give exactly one of hide, show, move')
    kind = kinds[0]
    unknown = sorted(set(leg) - {kind} - set(KINDS[kind]))
    if unknown:
        raise ScriptError('unknown key %s for a %s (known: %s)' % (
            ', '.join(unknown), kind, ', '.join((kind,) + KINDS[kind])))
    if kind == 'hide':
        return Leg('hide', None, None, _seconds(leg['hide'], 'the hide'))
    place = leg[kind]
    if (not isinstance(place, (list, tuple)) or len(place) != 2
            or not all(_finite(v) for v in place)):
        raise ScriptError('the place must be [x, y], two finite numbers')
    place = (float(place[0]), float(place[1]))
    if arena is not None and not (arena.x_min <= place[0] <= arena.x_max
                                  and arena.y_min <= place[1] <= arena.y_max):
        raise ScriptError('the place (%g, %g) is outside the arena x %g..%g, y %g..%g'
                          % (place + tuple(arena[:4])))
    stay = _seconds(leg.get('stay', 0.0), 'stay')
    if kind == 'show':
        return Leg('show', place, None, stay)
    speed = leg.get('speed')
    if not _finite(speed) or speed <= 0:
        raise ScriptError('speed must be a positive number of m/s, got %s' % _shown(speed))
    return Leg('move', place, float(speed), stay)


def _seconds(value, what):
    if not _finite(value):
        raise ScriptError('%s must be a finite number of seconds, got %s' % (what, _shown(value)))
    if value < 0:
        raise ScriptError('%s is negative (%g s)' % (what, value))
    return float(value)


def _shown(value):
    try:
        text = json.dumps(value, separators=(', ', ': '))
    except (TypeError, ValueError):
        text = repr(value)
    return text if len(text) <= 80 else text[:77] + '...'


def from_legs(legs, arena=None, given=None):
    """A :class:`Script` of legs given by hand (JSON's dicts or :class:`Leg`),
    checked (:func:`parse_legs`): ``arena``, when given, holds every place."""
    if legs and all(isinstance(leg, Leg) for leg in legs):
        legs = to_json_legs(legs)
    return _compile(parse_legs(legs, arena), options(given), None)


def to_json_legs(legs):
    """Legs as the JSON format writes them (the ground truth carries them)."""
    out = []
    for leg in legs:
        if leg.kind == 'hide':
            out.append({'hide': leg.stay})
        elif leg.kind == 'show':
            out.append({'show': list(leg.place), 'stay': leg.stay})
        else:
            out.append({'move': list(leg.place), 'speed': leg.speed, 'stay': leg.stay})
    return out


def _compile(legs, o, seed):
    """The timeline: one segment per hide, show and stay, two per move; its
    times to the microsecond, as :func:`play` reads them."""
    first = next((leg.place for leg in legs if leg.place is not None), None)
    x, y = first if first is not None else (0.0, 0.0)
    hidden, t, segments = True, 0.0, []
    for leg in legs:
        if leg.kind == 'hide':
            hidden = True
        elif leg.kind == 'show':
            x, y = leg.place
            hidden = False
        else:           # shown (parse_legs): from where it is
            arrive = round(t + math.hypot(leg.place[0] - x, leg.place[1] - y) / leg.speed, 6)
            segments.append(Segment(t, arrive, x, y, leg.place[0], leg.place[1], False))
            t = arrive
            x, y = leg.place
        segments.append(Segment(t, round(t + leg.stay, 6), x, y, x, y, hidden))
        t = segments[-1].t1
    return Script(tuple(legs), tuple(segments), tuple(s.t0 for s in segments), seed,
                  o.duration, o.ground_z)


def play(script, t):
    """Where the ball of ``script`` is at script time ``t`` (s): a
    :class:`BallPose`. Before 0 as at 0; after the last leg, as it ended.
    ``t`` is taken to the microsecond: a time that is a whole number of steps
    (a stamp, ``steps * time_step``) falls on the same side of a hide or a
    show however its float was summed."""
    t = round(t, 6)
    i = max(0, bisect.bisect_right(script.starts, t) - 1)
    seg = script.segments[i]
    span = seg.t1 - seg.t0
    f = min(max((t - seg.t0) / span, 0.0), 1.0) if span > 0 else 1.0
    moving = span > 0 and seg.t0 <= t < seg.t1 and (seg.x0, seg.y0) != (seg.x1, seg.y1)
    return BallPose(seg.x0 + f * (seg.x1 - seg.x0), seg.y0 + f * (seg.y1 - seg.y0),
                    HIDDEN_Z if seg.hidden else script.ground_z, seg.hidden,
                    (seg.x1 - seg.x0) / span if moving else 0.0,
                    (seg.y1 - seg.y0) / span if moving else 0.0)


def summary(script):
    """One line: what the course holds (for the simulator's log)."""
    kinds = [leg.kind for leg in script.legs]
    end = script.segments[-1].t1
    return ('%s, %d legs over %.0f s: %d places, %d hides'
            % ('seed %d' % script.seed if script.seed is not None else 'given by hand',
               len(kinds), end, kinds.count('show') + kinds.count('move'), kinds.count('hide')))

"""The grammar of everything a person (or a node) types, as plain Python.

Each parser returns a command tuple or raises :class:`CommandError`, whose
message says what was wrong and what is accepted, ready for one log line.
"""
import math
from collections import namedtuple

from exp_assignment2.world import ARENA_GOAL_LIMIT, GRID_MAX, GRID_MIN

BallCommand = namedtuple('BallCommand', 'kind x y')     # kind: go_to hide show auto stop
VoiceCommand = namedtuple('VoiceCommand', 'kind x y')   # kind: play go_to
MotionCommand = namedtuple('MotionCommand', 'kind x y')  # kind: go_home go_rand go_to

BALL_USAGE = ("accepted: 'go to X Y' (X, Y in [-%g, %g] m), 'hide', 'show', 'auto', 'stop'"
              % (ARENA_GOAL_LIMIT, ARENA_GOAL_LIMIT))
VOICE_USAGE = ("accepted: 'play', 'hey buddy', 'go to X Y' (X, Y whole numbers in [%d, %d])"
               % (GRID_MIN, GRID_MAX))
MOTION_USAGE = ("accepted: 'go_home', 'go_rand', 'go to X Y' (X, Y whole numbers in [%d, %d])"
                % (GRID_MIN, GRID_MAX))


class CommandError(ValueError):
    """A command that is not executed; the message says why and what is accepted."""


def _words(text):
    if not isinstance(text, str):
        raise CommandError('not text: %r' % (text,))
    return text.strip().lower().split()


def _go_to(words, text, usage, parse, check, bounds):
    if len(words) != 4 or words[:2] != ['go', 'to']:
        raise CommandError("%r is not a command; %s" % (text, usage))
    try:
        x, y = parse(words[2]), parse(words[3])
    except ValueError:
        raise CommandError("%r: X and Y must be numbers; %s" % (text, usage))
    if not check(x, y):
        raise CommandError("%r: (%s, %s) is outside %s; %s" % (text, words[2], words[3],
                                                               bounds, usage))
    return x, y


def _finite_float(word):
    value = float(word)
    if not math.isfinite(value):
        raise ValueError(word)
    return value


def parse_ball_command(text):
    """``/ball/command``: 'go to X Y', 'hide', 'show', 'auto' or 'stop'."""
    words = _words(text)
    if len(words) == 1 and words[0] in ('hide', 'show', 'auto', 'stop'):
        return BallCommand(words[0], None, None)
    if not words:
        raise CommandError('empty command; %s' % BALL_USAGE)
    x, y = _go_to(words, text, BALL_USAGE, _finite_float,
                  lambda x, y: abs(x) <= ARENA_GOAL_LIMIT and abs(y) <= ARENA_GOAL_LIMIT,
                  'the arena [-%g, %g]' % (ARENA_GOAL_LIMIT, ARENA_GOAL_LIMIT))
    return BallCommand('go_to', x, y)


def _grid_int(word):
    value = int(word)      # rejects '2.5', 'nan', 'two'
    return value


def _on_grid(x, y):
    return GRID_MIN <= x <= GRID_MAX and GRID_MIN <= y <= GRID_MAX


GRID_BOUNDS = 'the grid [%d, %d]' % (GRID_MIN, GRID_MAX)


def parse_voice(text):
    """``/voice``: 'play', 'hey buddy' or 'go to X Y' on the grid."""
    words = _words(text)
    if words in (['play'], ['hey', 'buddy']):
        return VoiceCommand('play', None, None)
    if not words:
        raise CommandError('nothing said; %s' % VOICE_USAGE)
    x, y = _go_to(words, text, VOICE_USAGE, _grid_int, _on_grid, GRID_BOUNDS)
    return VoiceCommand('go_to', x, y)


def parse_motion_command(text):
    """``/command``: 'go_home', 'go_rand' or 'go to X Y' on the grid."""
    words = _words(text)
    if len(words) == 1 and words[0] in ('go_home', 'go_rand'):
        return MotionCommand(words[0], None, None)
    if not words:
        raise CommandError('empty command; %s' % MOTION_USAGE)
    x, y = _go_to(words, text, MOTION_USAGE, _grid_int, _on_grid, GRID_BOUNDS)
    return MotionCommand('go_to', x, y)


def parse_or_report(parser, text, report):
    """``parser(text)``, or None after ``report(reason)`` when it is refused."""
    try:
        return parser(text)
    except CommandError as exc:
        report(str(exc))
        return None


def format_go_to(x, y):
    """The text of a go-to command, as the nodes publish it."""
    return 'go to %d %d' % (x, y) if isinstance(x, int) else 'go to %g %g' % (x, y)

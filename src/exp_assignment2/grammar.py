"""The grammar of everything a person (or a node) types, as plain Python.

Each parser returns a command tuple or raises :class:`CommandError`, whose
message quotes the input (at most :data:`QUOTE_LIMIT` characters), says what
was wrong and what is accepted: ready for one log line.

The rules are strict on purpose: words are separated by ASCII spaces and
tabs; numbers are ASCII digits with an optional sign, and a decimal point
only where the interface takes one; letters are case-insensitive ASCII.
Anything else (other scripts' digits, full-width forms, underscores inside
numbers, control characters, exotic spaces) is refused.
"""
import re
from collections import namedtuple

from exp_assignment2 import arena, grid

BallCommand = namedtuple('BallCommand', 'kind x y')      # kind: go_to hide show auto stop
VoiceCommand = namedtuple('VoiceCommand', 'kind x y')    # kind: play go_to
MotionCommand = namedtuple('MotionCommand', 'kind x y')  # kind: go_home go_rand go_to

QUOTE_LIMIT = 80
NUMBER_LIMIT = 20       # characters in one number: no 5000-digit "1" reaches int()
_SEPARATORS = re.compile(r'[ \t]+')
_DECIMAL = re.compile(r'[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)')
_INTEGER = re.compile(r'[+-]?[0-9]+')
_ALLOWED = frozenset('\t' + ''.join(chr(c) for c in range(0x20, 0x7f)))

BALL_USAGE = ("accepted: 'go to X Y' (X, Y decimal numbers in [-%g, %g] m), "
              "'hide', 'show', 'auto', 'stop'" % (arena.GOAL_LIMIT, arena.GOAL_LIMIT))
VOICE_USAGE = ("accepted: 'play', 'hey buddy', 'go to X Y' (X, Y whole numbers in [%d, %d])"
               % (grid.GRID_MIN, grid.GRID_MAX))
MOTION_USAGE = ("accepted: 'go_home', 'go_rand', 'go to X Y' (X, Y whole numbers in [%d, %d])"
                % (grid.GRID_MIN, grid.GRID_MAX))


class CommandError(ValueError):
    """A command that is not executed; the message says why and what is accepted."""


def quote(text, limit=QUOTE_LIMIT):
    """``text`` quoted for a log line: escaped, at most ``limit`` characters of it."""
    if not isinstance(text, str):
        text = str(text)
    shown = repr(text[:limit])
    if len(text) > limit:
        shown += '\u2026 (%d chars)' % len(text)
    return shown


def show_number(value):
    """A number as every refusal prints it: at most 10 significant digits,
    exponents for the huge and tiny (1e+308, -0, nan, -inf, 2.5)."""
    try:
        return '%.10g' % value
    except TypeError:
        return quote(value)


def show_numbers(values):
    """Numbers as a tuple, ``(x, y, z)``, each as :func:`show_number` prints it."""
    return '(%s)' % ', '.join(show_number(v) for v in values)


def _words(text, usage):
    if not isinstance(text, str):
        raise CommandError('not text: %s; %s' % (quote(text), usage))
    for i, char in enumerate(text):
        if char not in _ALLOWED:
            raise CommandError('%s: character %d (%s) is not allowed: use ASCII letters, '
                               'digits, signs and points, separated by spaces or tabs; %s'
                               % (quote(text), i + 1, ascii(char), usage))
    words = [w for w in _SEPARATORS.split(text.lower()) if w]
    if not words:
        raise CommandError('empty command; %s' % usage)
    return words


def _go_to(words, text, usage, number, kind, check, bounds):
    if len(words) != 4 or words[:2] != ['go', 'to']:
        raise CommandError('%s is not a command; %s' % (quote(text), usage))
    if not (number.fullmatch(words[2]) and number.fullmatch(words[3])):
        raise CommandError('%s: X and Y must be %s; %s' % (quote(text), kind, usage))
    if max(len(words[2]), len(words[3])) > NUMBER_LIMIT:
        raise CommandError('%s: X and Y must be %s of at most %d characters; %s'
                           % (quote(text), kind, NUMBER_LIMIT, usage))
    x, y = (float(w) if number is _DECIMAL else int(w) for w in words[2:])
    if not check(x, y):
        raise CommandError('%s: %s is outside %s; %s'
                           % (quote(text), show_numbers((x, y)), bounds, usage))
    return x, y


def parse_ball_command(text):
    """``/ball/command``: 'go to X Y' (metres), 'hide', 'show', 'auto' or 'stop'."""
    words = _words(text, BALL_USAGE)
    if len(words) == 1 and words[0] in ('hide', 'show', 'auto', 'stop'):
        return BallCommand(words[0], None, None)
    x, y = _go_to(words, text, BALL_USAGE, _DECIMAL, 'decimal numbers', arena.in_arena,
                  'the arena [-%g, %g]' % (arena.GOAL_LIMIT, arena.GOAL_LIMIT))
    return BallCommand('go_to', x, y)


GRID_BOUNDS = 'the grid [%d, %d]' % (grid.GRID_MIN, grid.GRID_MAX)


def parse_voice(text):
    """``/voice``: 'play', 'hey buddy' or 'go to X Y' on the grid."""
    words = _words(text, VOICE_USAGE)
    if words in (['play'], ['hey', 'buddy']):
        return VoiceCommand('play', None, None)
    x, y = _go_to(words, text, VOICE_USAGE, _INTEGER, 'whole numbers', grid.on_grid,
                  GRID_BOUNDS)
    return VoiceCommand('go_to', x, y)


def parse_motion_command(text):
    """``/command``: 'go_home', 'go_rand' or 'go to X Y' on the grid."""
    words = _words(text, MOTION_USAGE)
    if len(words) == 1 and words[0] in ('go_home', 'go_rand'):
        return MotionCommand(words[0], None, None)
    x, y = _go_to(words, text, MOTION_USAGE, _INTEGER, 'whole numbers', grid.on_grid,
                  GRID_BOUNDS)
    return MotionCommand('go_to', x, y)


def format_go_to(x, y):
    """The text of a go-to command, as the nodes publish it."""
    if isinstance(x, int) and isinstance(y, int):
        return 'go to %d %d' % (x, y)
    return 'go to %g %g' % (x, y)

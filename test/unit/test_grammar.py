"""The command grammar: what is accepted, and one clear refusal for the rest."""
import pytest

from exp_assignment2.grammar import (CommandError, format_go_to, parse_ball_command,
                                     parse_motion_command, parse_voice, quote, show_number,
                                     show_numbers)
from exp_assignment2.refusal import parse_or_refuse


@pytest.mark.parametrize('text,expected', [
    ('go to 1 2', ('go_to', 1.0, 2.0)),
    ('  GO  TO -7.5 8 ', ('go_to', -7.5, 8.0)),
    ('go\tto\t+3 .5', ('go_to', 3.0, 0.5)),
    ('go to 8. -8', ('go_to', 8.0, -8.0)),
    ('hide', ('hide', None, None)),
    ('show', ('show', None, None)),
    ('auto', ('auto', None, None)),
    ('Stop', ('stop', None, None)),
])
def test_ball_commands_accepted(text, expected):
    assert tuple(parse_ball_command(text)) == expected


@pytest.mark.parametrize('text', ['', '   ', 'go to 1', 'go to a b', 'go to 9 0',
                                  'go to 0 -8.5', 'go to nan 1', 'go to inf 0', 'jump',
                                  'go to 1 2 3', 'go 1 2', 'go to 1e1 2', 'go to 0x1 2',
                                  'go to 1_0 2', 'go to - 2', 'go to 1..2 3', 'go to +-1 2'])
def test_ball_commands_rejected_with_usage(text):
    with pytest.raises(CommandError) as err:
        parse_ball_command(text)
    assert 'accepted:' in str(err.value)


@pytest.mark.parametrize('text,expected', [
    ('play', ('play', None, None)),
    ('hey buddy', ('play', None, None)),
    ('Hey  Buddy', ('play', None, None)),
    ('go to 4 7', ('go_to', 4, 7)),
    ('go to 0 10', ('go_to', 0, 10)),
    ('go to +4 007', ('go_to', 4, 7)),
])
def test_voice_accepted(text, expected):
    assert tuple(parse_voice(text)) == expected


@pytest.mark.parametrize('text', ['', 'go to 4', 'go to four seven', 'go to -1 3',
                                  'go to 11 2', 'go to 2.5 3', 'hello', 'go to 1 2 3',
                                  'go to 2. 3', 'heybuddy', 'play play'])
def test_voice_rejected(text):
    with pytest.raises(CommandError, match='accepted:'):
        parse_voice(text)


@pytest.mark.parametrize('text', [
    'go to \u0662 \u0663',          # Arabic-Indic digits
    'go to \uff14 2',               # full-width 4
    'go to 1_0 2',                  # underscore inside a number
    'go to 1\u00a02 3',             # no-break space
    'go\u3000to 1 2',               # ideographic space
    'go to 1 2\n',                  # a newline
    'go to 1 2\r',
    'go to\x00 1 2',                # NUL
    'play\x1b[31m',                 # an escape sequence
    'pl\u0430y',                    # Cyrillic a
    '\u0130'                        # dotted capital I (lower() turns it into two letters)
])
@pytest.mark.parametrize('parser', [parse_voice, parse_ball_command, parse_motion_command])
def test_only_ascii_digits_letters_spaces_and_tabs_are_accepted(parser, text):
    with pytest.raises(CommandError) as err:
        parser(text)
    assert 'accepted:' in str(err.value)


def test_a_bad_character_is_named_with_its_position():
    with pytest.raises(CommandError, match=r"character 7 \('\\uff14'\)"):
        parse_voice('go to \uff14 2')


@pytest.mark.parametrize('text,expected', [
    ('go_home', ('go_home', None, None)),
    ('go_rand', ('go_rand', None, None)),
    ('go to 3 9', ('go_to', 3, 9)),
])
def test_motion_commands(text, expected):
    assert tuple(parse_motion_command(text)) == expected


@pytest.mark.parametrize('text', ['', 'go home', 'go to 3', 'go to 3 99', 'go to -3 3',
                                  'go_home now'])
def test_motion_commands_rejected(text):
    with pytest.raises(CommandError, match='accepted:'):
        parse_motion_command(text)


@pytest.mark.parametrize('value', [None, 42, b'play', ['play']])
def test_non_text_is_rejected(value):
    with pytest.raises(CommandError, match='not text'):
        parse_voice(value)


def test_a_point_outside_is_printed_as_every_number_is():
    """At most 10 significant digits (20 digits were printed in full)."""
    with pytest.raises(CommandError) as voice:
        parse_voice('go to 99999999999999999999 1')
    assert "(1e+20, 1) is outside the grid" in str(voice.value)
    with pytest.raises(CommandError) as ball:
        parse_ball_command('go to -0 1000.50')
    assert "(-0, 1000.5) is outside the arena" in str(ball.value)


def test_a_long_input_is_quoted_to_80_characters_with_its_length():
    text = 'x' * 1000000
    with pytest.raises(CommandError) as err:
        parse_ball_command(text)
    message = str(err.value)
    assert "'" + 'x' * 80 + "'\u2026 (1000000 chars)" in message
    assert len(message) < 400


def test_quote_escapes_control_characters():
    assert quote('a\nb') == "'a\\nb'"
    assert quote('a' * 81).endswith('\u2026 (81 chars)')


def test_parse_or_refuse_reports_the_reason_once():
    reasons = []
    assert parse_or_refuse(parse_voice, 'fly', reasons.append) is None
    assert len(reasons) == 1 and 'accepted:' in reasons[0]
    assert parse_or_refuse(parse_voice, 'play', reasons.append).kind == 'play'
    assert len(reasons) == 1


def test_format_go_to_round_trips_through_the_parsers():
    assert parse_voice(format_go_to(6, 2)) == ('go_to', 6, 2)
    assert parse_ball_command(format_go_to(-2.5, 3.0))[1:] == (-2.5, 3.0)


@pytest.mark.parametrize('parser', [parse_ball_command, parse_voice, parse_motion_command])
def test_a_number_of_thousands_of_digits_is_refused_not_a_crash(parser):
    # int() refuses strings of over 4300 digits with a plain ValueError
    text = 'go to %s1 2' % ('0' * 5000)
    with pytest.raises(CommandError) as err:
        parser(text)
    assert 'at most 20 characters' in str(err.value) and '(5009 chars)' in str(err.value)


@pytest.mark.parametrize('parser', [parse_ball_command, parse_voice, parse_motion_command])
def test_leading_zeros_are_still_a_number(parser):
    assert tuple(parser('go to 0003 +02'))[1:] == (3, 2)


@pytest.mark.parametrize('value,text', [
    (1e308, '1e+308'), (-1e15, '-1e+15'), (-0.0, '-0'), (0, '0'), (2.5, '2.5'), (7, '7'),
    (float('-inf'), '-inf'), (float('nan'), 'nan'), (8.0000001, '8.0000001'),
    (2147483647.0, '2147483647'), (31.35, '31.35'), ('x', "'x'")])
def test_a_number_in_a_refusal_is_short_and_printed_one_way(value, text):
    assert show_number(value) == text


def test_numbers_are_printed_as_a_tuple():
    assert show_numbers((float('inf'), 0.0, -1e308)) == '(inf, 0, -1e+308)'

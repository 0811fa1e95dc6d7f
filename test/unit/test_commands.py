"""The command grammar: what is accepted, and a clear error for the rest."""
import pytest

from exp_assignment2.commands import (CommandError, parse_ball_command, parse_motion_command,
                                      parse_voice)


@pytest.mark.parametrize('text,expected', [
    ('go to 1 2', ('go_to', 1.0, 2.0)),
    ('  GO  TO -7.5 8 ', ('go_to', -7.5, 8.0)),
    ('hide', ('hide', None, None)),
    ('show', ('show', None, None)),
    ('auto', ('auto', None, None)),
    ('Stop', ('stop', None, None)),
])
def test_ball_commands_accepted(text, expected):
    assert tuple(parse_ball_command(text)) == expected


@pytest.mark.parametrize('text', ['', '   ', 'go to 1', 'go to a b', 'go to 9 0',
                                  'go to 0 -8.5', 'go to nan 1', 'go to inf 0', 'jump',
                                  'go to 1 2 3', 'go 1 2'])
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
])
def test_voice_accepted(text, expected):
    assert tuple(parse_voice(text)) == expected


@pytest.mark.parametrize('text', ['', 'go to 4', 'go to four seven', 'go to -1 3',
                                  'go to 11 2', 'go to 2.5 3', 'hello', 'go to 1 2 3'])
def test_voice_rejected(text):
    with pytest.raises(CommandError, match='accepted:'):
        parse_voice(text)


@pytest.mark.parametrize('text,expected', [
    ('go_home', ('go_home', None, None)),
    ('go_rand', ('go_rand', None, None)),
    ('go to 3 9', ('go_to', 3, 9)),
])
def test_motion_commands(text, expected):
    assert tuple(parse_motion_command(text)) == expected


@pytest.mark.parametrize('text', ['', 'go home', 'go to 3', 'go to 3 99', 'go to -3 3'])
def test_motion_commands_rejected(text):
    with pytest.raises(CommandError, match='accepted:'):
        parse_motion_command(text)


def test_non_text_is_rejected():
    with pytest.raises(CommandError):
        parse_voice(None)


def test_parse_or_report_reports_the_reason_once():
    from exp_assignment2.commands import parse_or_report
    reasons = []
    assert parse_or_report(parse_voice, 'fly', reasons.append) is None
    assert len(reasons) == 1 and 'accepted:' in reasons[0]
    assert parse_or_report(parse_voice, 'play', reasons.append).kind == 'play'
    assert len(reasons) == 1

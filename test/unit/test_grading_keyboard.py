"""The keyboard in a grading: grading.yaml's lines to type with their command,
and a read nobody answered said once on the pages (no ROS)."""
import pytest


def test_lines_to_type_go_with_their_command():
    from exp_assignment2.grading.plan import starts
    from exp_assignment2.grading.plan.teacher_file import TeacherFileError, _check_command
    given = {'run': 'rosrun p ask.py', 'input': [{'at': 3, 'text': 'm'}]}
    _check_command(given, 'grading.yaml')
    _check_command({'run': 'roslaunch p a.launch', 'input': {'ask.py': [{'at': 0, 'text': ''}]}},
                   'grading.yaml')
    plan = starts.from_teacher([given, 'rosrun p dog.py'], 5)
    assert plan[0]['input'] == [{'at': 3, 'text': 'm'}] and 'input' not in plan[1]
    for bad in ([{'at': -1, 'text': 'm'}], [{'at': 1, 'text': 'a\nb'}], [{'when': 1}],
                {'ask.py': 'm'}, 'm'):
        with pytest.raises(TeacherFileError, match='input'):
            _check_command({'run': 'rosrun p ask.py', 'input': bad}, 'grading.yaml')


def test_a_read_nobody_answered_is_said_once_with_its_command():
    from exp_assignment2.grading.judge.seen import keyboard_waits
    logs = [('logs/command-1.log', 'Command: [original-env] waited for keyboard input at '
             'scripts/ask.py:37\n[original-env] waited for keyboard input at scripts/ask.py:37'),
            ('ros_home/log/x/ask-2.log', 'nothing')]
    assert keyboard_waits(logs, {1: 'rosrun p ask.py'}) == [
        {'where': 'scripts/ask.py:37', 'command': 'rosrun p ask.py'}]

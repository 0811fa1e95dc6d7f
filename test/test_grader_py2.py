"""The grader end to end on a submission written for Python 2 with keyboard
nodes (test/py2_fixtures.py, graded with the fixture folder by
test/grading_run.py): its files run as Python 2 ran them, one keyboard node
gets grading.yaml's lines at their simulated times, the other waits as on a
terminal nobody types into, and the page says where."""
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

pytestmark = pytest.mark.xdist_group('grader')


def test_python_2_code_and_the_keyboard(graded):
    run = graded['runs']['py2_keyboard']
    assert run['verdict'] == 'passed' and run['error_count'] == 0, run['reason']
    assert [w['where'] for w in sorted(run['keyboard'], key=lambda w: w['where'])] == [
        'scripts/ball_request.py:5', 'scripts/human.py:5']
    with open(os.path.join(graded['out'], 'runs', 'py2_keyboard', 'work', 'logs',
                           'command-0.log'), errors='replace') as f:
        said = f.read()
    assert 'got m' in said and 'got d' in said          # grading.yaml's input: typed
    assert said.count('read as Python 2 (translated in memory)') == 3
    assert 'gain turn = 2' in said                      # print statements, iteritems
    for folder in ('pages', 'feedback'):
        with open(os.path.join(graded['out'], folder, 'py2_keyboard.html')) as f:
            page = f.read()
        assert 'waited for keyboard input at <code>scripts/human.py:5</code>' in page

"""Gradescope's autograder end to end (docs/grading.md, "Gradescope"): the entry
point grades a temporary /autograder-shaped tree's submission (the fixture dog
that works) into its results/results.json, in Gradescope's documented fields."""
import json
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, 'unit'))
import grading_fixtures  # noqa: E402
from test_grading_marks import check_format  # noqa: E402

pytestmark = pytest.mark.xdist_group('grader')


def test_the_autograder_grades_a_submission_into_results_json(tmp_path):
    root = tmp_path / 'autograder'
    grading_fixtures.make_folder(str(root / 'submission'), ['works'])
    proc = subprocess.run(['bash', os.path.join(REPO, 'tools', 'gradescope', 'run_autograder'),
                           '--root', str(root), '--', '--duration', '30',
                           '--real-time-factor', '2', '--jobs', '1'],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=900)
    assert proc.returncode == 0, proc.stdout[-3000:]
    with open(str(root / 'results' / 'results.json')) as f:
        data = json.load(f)
    check_format(data)
    # 30 s of a ball that never moved or hid: the behaviours it gave no occasion for are
    # the teacher's to mark (no score, not a 0); every other check passed
    assert data['score'] == 60, data
    assert [t['name'] for t in data['tests']] == [
        'reaches the ball', 'first reach', 'head turns both ways at the ball',
        'follows the moving ball', 'gives up a hidden ball', 'sleeps at home', 'wanders',
        'path length', 'no Python error']
    assert [t['max_score'] for t in data['tests']] == [20, 10, 15, 10, 10, 10, 10, 5, 10]
    pending = [t['name'] for t in data['tests'] if 'score' not in t]
    assert pending == ['follows the moving ball', 'gives up a hidden ball', 'sleeps at home',
                       'wanders']
    assert all(t['status'] == 'passed' and t['score'] == t['max_score'] for t in data['tests']
               if t['name'] not in pending)
    assert data['stdout_visibility'] == 'hidden' and data['execution_time'] > 0
    with open(str(root / 'results' / 'feedback.html')) as f:
        page = f.read()
    assert str(tmp_path) not in page and 'Score: <b>60</b> / 100' in page
    assert '40 points are for your teacher to mark by hand' in page

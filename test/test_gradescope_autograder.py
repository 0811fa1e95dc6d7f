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
    assert data['score'] == 100, data
    assert [t['name'] for t in data['tests']] == ['reaches the ball', 'first reach',
                                                  'head turns at the ball', 'path length',
                                                  'no Python error']
    assert [t['max_score'] for t in data['tests']] == [30, 15, 25, 10, 20]
    assert all(t['status'] == 'passed' and t['score'] == t['max_score'] for t in data['tests'])
    assert data['stdout_visibility'] == 'hidden' and data['execution_time'] > 0
    with open(str(root / 'results' / 'feedback.html')) as f:
        page = f.read()
    assert str(tmp_path) not in page and 'Score: <b>100</b> / 100' in page

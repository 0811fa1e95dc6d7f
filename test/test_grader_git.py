"""``bash tools/run grade FOLDER --deadline TIME`` of a folder holding a git
repository, as GitHub Classroom clones one (issue 52): the commit before the
deadline is built and run (the dog that works), not the later one (a dog that
raises); the pages name the commit and the commit after it; the gradebooks
are written; and nothing of the repository's hostile configuration or hooks
ran on the teacher's machine. One short grading of one submission."""
import csv
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
from git_helpers import commit, git, make_hostile  # noqa: E402

pytestmark = pytest.mark.xdist_group('grader_git')


def test_a_repository_graded_at_its_deadline(tmp_path):
    folder = str(tmp_path / 'class')
    repo = os.path.join(folder, 'rossi')
    grading_fixtures._package(repo)
    git(repo, 'init', '-q', '-b', 'main')
    first = commit(repo, 'the dog plays', '2025-03-01T10:00:00+01:00')
    grading_fixtures._replace(repo, grading_fixtures.DOG, grading_fixtures.RAISES)
    commit(repo, 'too late and broken', '2025-03-03T10:00:00+01:00')
    marks = str(tmp_path / 'marks')
    os.makedirs(marks)
    make_hostile(repo, marks)
    with open(os.path.join(folder, 'grading.yaml'), 'w') as f:
        f.write("students: {rossi: 'S0042'}\ngradebook: {assignment: Assignment 2}\n")
    out = str(tmp_path / 'report')
    proc = subprocess.run(['bash', os.path.join(REPO, 'tools', 'run'), 'grade', folder,
                           '--out', out, '--duration', '20', '--real-time-factor', '2',
                           '--deadline', '2025-03-02T00:00:00+01:00'],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=1800)
    assert proc.returncode == 0, proc.stdout[-3000:]
    assert 'rossi: graded at %s' % first[:7] in proc.stdout
    with open(os.path.join(out, 'report.json')) as f:
        data = json.load(f)
    (summary,) = data['submissions']
    assert summary['git']['commit'] == first and summary['git']['after'] == 1
    assert summary['verdict'] not in ('not_built', 'grader_error'), summary['reason']
    errors = next(c for c in summary['checks'] if c['metric'] == 'python_errors')
    assert errors['value'] == 0, 'the later commit (a dog that raises) was run'
    page = open(os.path.join(out, 'pages', 'rossi.html')).read()
    assert 'Commit graded' in page and first[:7] in page and '1 commit after it not graded' \
        in page
    with open(os.path.join(out, 'gradebook-moodle.csv'), newline='') as f:
        rows = list(csv.reader(f))
    assert rows[0][:3] == ['Identifier', 'Submission', 'Assignment 2']
    assert rows[1][:2] == ['S0042', 'rossi'] and rows[1][2] == '%g' % summary['score']
    assert os.path.isfile(os.path.join(out, 'gradebook-canvas.csv'))
    assert os.listdir(marks) == [], 'something of the repository ran: %s' % os.listdir(marks)
    assert git(repo, 'rev-parse', 'HEAD') != first      # the folder is only ever read

"""The grading of the fixture folder (test/grading_fixtures.py) that the
grader's end-to-end tests read, made once a test session (test/conftest.py
registers :func:`graded`): ``bash tools/run grade SUBMISSIONS --out REPORT``
as a teacher runs it, in short runs at twice real time."""
import json
import os
import subprocess

import pytest

import grading_fixtures

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
GRADE = ['bash', os.path.join(REPO, 'tools', 'run'), 'grade']
# short runs, at twice real time: the fixture dog reaches its ball in 5 s
FAST = ['--duration', '30', '--real-time-factor', '2', '--jobs', '2']


def snapshot(folder):
    out = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            st = os.lstat(os.path.join(root, name))
            out[os.path.relpath(os.path.join(root, name), folder)] = (st.st_size, st.st_mtime_ns,
                                                                     st.st_mode)
    return out


@pytest.fixture(scope='session')
def graded(tmp_path_factory):
    base = tmp_path_factory.mktemp('grader')
    folder = grading_fixtures.make_folder(str(base / 'class'))
    # a file beside the folder, as another course's files would be
    canary = base / 'canary.txt'
    canary.write_text('untouched')
    before = snapshot(str(base))
    out = str(base / 'report')
    proc = subprocess.run(GRADE + [folder, '--out', out] + FAST, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=1500)
    assert os.path.exists(os.path.join(out, 'report.json')), (
        'grade exited %s with no report:\n%s' % (proc.returncode, proc.stdout[-3000:]))
    with open(os.path.join(out, 'report.json')) as f:
        report = json.load(f)
    return {'base': str(base), 'folder': folder, 'out': out, 'before': before, 'proc': proc,
            'report': report,
            'by_name': {s['name']: s for s in report['submissions']},
            'runs': {r['label']: r for r in report['runs']}}

"""A teacher's grading stopped and started again, and graded again with
another profile, end to end (``bash tools/run grade`` on a small folder of
its own: the dog that works, one whose dog dies with a traceback, one whose
C++ does not build,
20 simulated s at twice real time, one run at a time).

- killed with SIGKILL half way (the teacher's process and all it started),
  no sandbox outlives it; started again with the same ``--out``, it keeps
  the runs that finished (their run ids unchanged), runs the rest, and gives
  the verdicts and scores of a grading never interrupted, and the control
  groups and scratch directories the killed one left are gone;
- Ctrl-C once: the running run finishes and is recorded, no other starts;
  twice: the running run is stopped now, nothing left running, no record;
- ``--report-only`` with a profile whose ``path length`` needs 50 m: the
  dog that passed fails its path check, and the report says whose mark
  changed (index, changes.csv), keeping the marks it published before.
"""
import csv
import glob
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import grading_fixtures  # noqa: E402

pytestmark = pytest.mark.xdist_group('grader_resume')
GRADE = ['bash', os.path.join(REPO, 'tools', 'run'), 'grade']
NAMES = ['works', 'raises', 'cpp_broken']
FAST = ['--duration', '20', '--real-time-factor', '2', '--jobs', '1']
CGROUPS = ('/sys/fs/cgroup/pids', '/sys/fs/cgroup/memory')


@pytest.fixture(scope='module')
def folder(tmp_path_factory):
    base = tmp_path_factory.mktemp('resume')
    return {'base': base, 'class': grading_fixtures.make_folder(str(base / 'class'), NAMES)}


def grade(folder, out, *extra, timeout=900):
    return subprocess.run(GRADE + [folder['class'], '--out', out] + FAST + list(extra),
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=timeout)


def start(folder, out, *extra):
    """The teacher's grade, in a process group of its own."""
    return subprocess.Popen(GRADE + [folder['class'], '--out', out] + FAST + list(extra),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, start_new_session=True)


def marks(out):
    with open(os.path.join(out, 'report.json')) as f:
        report = json.load(f)
    return {s['name']: (s['verdict'], s['score']) for s in report['submissions']}


def run_ids(out):
    found = {}
    for path in glob.glob(os.path.join(out, 'runs', '*', 'record', 'run.json')):
        with open(path) as f:
            run = json.load(f)
        found[run['label']] = run['run_id']
    return found


def sandboxes(out):
    """The pids of the bubblewrap processes of gradings into ``out`` (each
    hides it from its run)."""
    found = []
    for cmdline in glob.glob('/proc/[0-9]*/cmdline'):
        try:
            with open(cmdline, 'rb') as f:
                words = f.read().split(b'\0')
        except OSError:
            continue
        if words and words[0].endswith(b'bwrap') and out.encode() in words:
            found.append(int(cmdline.split('/')[2]))
    return found


def group_of(pgid):
    out = subprocess.run(['ps', '-e', '-o', 'pid=,pgid='], stdout=subprocess.PIPE,
                         universal_newlines=True).stdout
    return [int(p) for p, g in (line.split() for line in out.splitlines()) if int(g) == pgid]


def left_by(pids):
    """Control groups and scratch directories named for these processes."""
    names = [n for root in CGROUPS for _, dirs, _ in os.walk(root) for n in dirs]
    names += os.listdir('/tmp')
    return [n for n in names for pid in pids
            if re.match(r'^exp2-(grade|teacher)-(.*-)?%d-[A-Za-z0-9_]+$' % pid, n)]


def wait_for(what, timeout, step=0.5):
    deadline = time.monotonic() + timeout
    while not what():
        assert time.monotonic() < deadline, 'timed out'
        time.sleep(step)


@pytest.fixture(scope='module')
def whole(folder):
    """The grading never interrupted."""
    out = str(folder['base'] / 'whole')
    proc = grade(folder, out)
    assert proc.returncode == 0, proc.stdout[-3000:]
    return out


def test_a_grading_killed_half_way_and_resumed_is_the_uninterrupted_one(folder, whole):
    out = str(folder['base'] / 'killed')
    teacher = start(folder, out)
    # half way: a run finished (its record whole) and the next one running
    wait_for(lambda: run_ids(out) and sandboxes(out), 600)
    time.sleep(3)
    before, pids = run_ids(out), group_of(teacher.pid)
    os.killpg(teacher.pid, signal.SIGKILL)
    teacher.wait(10)
    # bubblewrap's --die-with-parent: no sandbox outlives the teacher's process
    wait_for(lambda: not sandboxes(out), 10)
    assert left_by(pids)        # what it would have removed: its scratch, its control groups
    proc = grade(folder, out)
    assert proc.returncode == 0, proc.stdout[-3000:]
    kept = len(before)
    assert 'resuming: %d run%s kept, %d to run' % (kept, '' if kept == 1 else 's',
                                                  len(NAMES) - kept) in proc.stdout
    after = run_ids(out)
    assert {label: after[label] for label in before} == before     # not run again
    assert set(after) == set(NAMES)
    assert marks(out) == marks(whole)
    assert left_by(pids) == []         # its control groups and scratch: removed
    with open(os.path.join(out, 'index.html')) as f:
        assert 'resumed an earlier one: %d run' % kept in f.read()


def test_ctrl_c_once_lets_the_running_run_finish_and_starts_no_other(folder):
    out = str(folder['base'] / 'once')
    teacher = start(folder, out, '--only', 'works', 'raises')
    wait_for(lambda: sandboxes(out), 600)
    time.sleep(2)
    teacher.send_signal(signal.SIGINT)
    output, _ = teacher.communicate(timeout=300)
    assert teacher.returncode == 130, output[-3000:]
    assert 'Ctrl-C: no new run starts; the running ones (1) finish' in output
    recorded = run_ids(out)
    assert len(recorded) == 1, output[-3000:]
    [label] = recorded
    with open(os.path.join(out, 'runs', label, 'record', 'run.json')) as f:
        run = json.load(f)
    assert run['ended_by'] == 'duration' and run['verdict'] in ('passed', 'failed_checks')
    with open(os.path.join(out, 'index.html')) as f:
        assert 'Stopped before its end' in f.read()


def test_ctrl_c_twice_stops_the_running_run_now(folder):
    out = str(folder['base'] / 'twice')
    teacher = start(folder, out, '--only', 'works', 'raises')
    wait_for(lambda: sandboxes(out), 600)
    time.sleep(2)
    pids = group_of(teacher.pid)
    teacher.send_signal(signal.SIGINT)
    time.sleep(1)
    teacher.send_signal(signal.SIGINT)
    stopped = time.monotonic()
    output, _ = teacher.communicate(timeout=120)
    assert teacher.returncode == 130, output[-3000:]
    assert time.monotonic() - stopped < 45, output[-3000:]
    assert 'Ctrl-C again: stopping the running ones (1) now' in output
    assert not sandboxes(out) and run_ids(out) == {}
    assert left_by(pids) == []         # its sandbox's control groups removed, and its scratch


def test_a_regrade_with_a_threshold_raised_lists_whose_marks_changed(folder, whole):
    out = str(folder['base'] / 'regraded')
    shutil.copytree(whole, out)
    with open(os.path.join(REPO, 'config', 'grading', 'dog.yaml')) as f:
        text = f.read()
    at = text.index('  - name: path length')
    strict = text[:at] + text[at:].replace('    min: 2.0', '    min: 50.0', 1)
    profile = folder['base'] / 'dog-strict.yaml'
    profile.write_text(strict.replace('name: dog\n', 'name: dog-strict\n', 1))
    proc = grade(folder, out, '--report-only', '--profile', str(profile), timeout=300)
    assert proc.returncode == 0, proc.stdout[-3000:]
    assert '1 mark changed since the report before (report 2 against 1)' in proc.stdout
    assert marks(out)['works'][0] == 'failed_checks' and marks(out)['works'][1] < 100
    assert {n: m for n, m in marks(out).items() if n != 'works'} == \
        {n: m for n, m in marks(whole).items() if n != 'works'}
    with open(os.path.join(out, 'changes.csv')) as f:
        rows = list(csv.DictReader(f))
    assert [(r['submission'], r['change'], r['verdict before'], r['verdict after'])
            for r in rows] == [('works', 'mark', 'passed', 'failed_checks')]
    changed = rows[0]['checks changed']         # the path's points are the profile's
    assert changed.startswith('path length: passed, ') and ' points then; failed' in changed
    with open(os.path.join(out, 'index.html')) as f:
        assert '<a href="changes.html"><b>1 mark changed</b></a>' in f.read()
    # the runs' own records are as their workers wrote them
    with open(os.path.join(out, 'runs', 'works', 'record', 'run.json')) as f:
        assert json.load(f)['verdict'] == 'passed'
    # judged again with the first profile: the marks it published come back, and
    # every run is judged as its worker judged it
    proc = grade(folder, out, '--report-only', timeout=300)
    assert proc.returncode == 0, proc.stdout[-3000:]
    assert marks(out) == marks(whole)
    with open(os.path.join(out, 'report.json')) as f:
        for run in json.load(f)['runs']:
            with open(os.path.join(out, 'runs', run['label'], 'record', 'run.json')) as g:
                recorded = json.load(g)
            for key in ('verdict', 'reason', 'checks', 'errors', 'died', 'launch_errors',
                        'roles'):
                assert run.get(key) == recorded.get(key), (run['label'], key)
    assert sorted(os.listdir(os.path.join(out, 'published'))) == ['001.json', '002.json',
                                                                  '003.json']

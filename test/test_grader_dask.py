"""The grader on a Dask cluster, as a teacher's lab runs it: a real
``dask-scheduler`` and two ``tools/run grade-worker`` processes on loopback
(free ports, each with its own ``runs`` count), and ``tools/run grade
--scheduler``. The verdicts are the local grading's (test_grader.py holds
those), the runs are spread over both workers, a worker killed with SIGKILL
in the middle of a run has that run done again by the other (and the report
says so), a worker that claims another package version is refused with both
versions named, an unreachable scheduler is one line in under 10 s, and
Ctrl-C on the teacher's side lets the running runs finish and records
them, and twice, or the teacher's process killed, leaves no run behind on
the workers.
"""
import json
import os
import signal
import socket
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import grading_fixtures  # noqa: E402

pytestmark = pytest.mark.xdist_group('grader_dask')
RUN = os.path.join(REPO, 'tools', 'run')
NAMES = ['works', 'raises', 'idle', 'cpp_broken']


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def start_worker(address, runs, log, **env):
    return subprocess.Popen(['bash', RUN, 'grade-worker', address, '--runs', str(runs),
                             '--no-nanny'], stdout=log, stderr=subprocess.STDOUT,
                            env=dict(os.environ, **env), start_new_session=True)


def workers_up(address, count, timeout=180):
    from distributed import Client
    deadline = time.monotonic() + timeout
    with Client(address, timeout=10) as client:
        while len(client.scheduler_info()['workers']) < count:
            assert time.monotonic() < deadline, 'the workers did not come up'
            time.sleep(0.5)


def sandboxes_of(pid):
    """bwrap processes under a worker process."""
    out = subprocess.run(['ps', '-e', '-o', 'pid=,ppid=,comm='], stdout=subprocess.PIPE,
                         universal_newlines=True).stdout.split('\n')
    children = {}
    for line in out:
        parts = line.split()
        if len(parts) == 3:
            children.setdefault(int(parts[1]), []).append((int(parts[0]), parts[2]))
    found, todo = [], [pid]
    while todo:
        for child, name in children.get(todo.pop(), []):
            todo.append(child)
            if name == 'bwrap':
                found.append(child)
    return found


@pytest.fixture(scope='module')
def cluster(tmp_path_factory):
    base = tmp_path_factory.mktemp('dask')
    port = free_port()
    address = 'tcp://127.0.0.1:%d' % port
    logs = [open(str(base / name), 'w') for name in ('scheduler.log', 'w1.log', 'w2.log')]
    scheduler = subprocess.Popen(['dask-scheduler', '--host', '127.0.0.1', '--port', str(port),
                                  '--dashboard-address', '127.0.0.1:%d' % free_port()],
                                 stdout=logs[0], stderr=subprocess.STDOUT,
                                 start_new_session=True)
    workers = [start_worker(address, 1, logs[1]), start_worker(address, 2, logs[2])]
    procs = [scheduler] + workers
    try:
        workers_up(address, 2)
        yield {'address': address, 'base': base, 'workers': workers,
               'folder': grading_fixtures.make_folder(str(base / 'class'), NAMES)}
    finally:
        for proc in procs:
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except OSError:
                pass
        for log in logs:
            log.close()


def records(out, label):
    """(the run's record as its worker or the teacher's side wrote it, the
    teacher's part beside it)."""
    found = []
    for name in ('run.json', 'teacher.json'):
        with open(os.path.join(out, 'runs', label, 'record', name)) as f:
            found.append(json.load(f))
    return found


def grade(cluster, out, *extra, timeout=900):
    return subprocess.run(['bash', RUN, 'grade', cluster['folder'], '--out', out,
                           '--scheduler', cluster['address'], '--duration', '25'] + list(extra),
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=timeout)


def test_the_verdicts_are_the_local_ones_and_runs_spread(cluster):
    out = str(cluster['base'] / 'report')
    proc = grade(cluster, out)
    assert proc.returncode == 0, proc.stdout[-3000:]
    assert 'Dask dashboard: http://127.0.0.1:' in proc.stdout
    with open(os.path.join(out, 'report.json')) as f:
        report = json.load(f)
    got = {s['name']: s['verdict'] for s in report['submissions']}
    assert got == {n: grading_fixtures.EXPECTED[n] for n in NAMES}
    workers = {r['teacher']['workers'][-1] for r in report['runs']}
    assert len(workers) == 2, workers
    # what the runs left on the workers came back: frames, ground truth, logs
    assert report['runs'][[r['label'] for r in report['runs']].index('works')]['truth'][
        'frames'] > 0
    assert os.path.exists(os.path.join(out, 'runs', 'cpp_broken', 'work', 'logs', 'build.log'))


def test_a_killed_worker_has_its_run_done_again(cluster):
    out = str(cluster['base'] / 'killed')
    teacher = subprocess.Popen(['bash', RUN, 'grade', cluster['folder'], '--out', out,
                                '--scheduler', cluster['address'], '--duration', '25',
                                '--only', 'works'], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, universal_newlines=True)
    deadline = time.monotonic() + 300
    victim = None
    while victim is None:
        assert time.monotonic() < deadline, 'no run started'
        for worker in cluster['workers']:
            if sandboxes_of(worker.pid):
                victim = worker
        time.sleep(0.5)
    time.sleep(5)                    # in the middle of the run
    os.killpg(victim.pid, signal.SIGKILL)
    cluster['workers'].remove(victim)       # the later tests' count, whatever follows here
    output, _ = teacher.communicate(timeout=600)
    assert teacher.returncode == 0, output[-3000:]
    run, teacher = records(out, 'works')
    assert run['verdict'] == 'passed'
    workers, notes = teacher['workers'], teacher['notes']
    lost = ('run again: its worker %s was lost in the middle of the run; done on %s'
            % tuple(workers[:2]))
    # a machine busy with other tests may starve the run done again: it is then run
    # a third time, alone, and says so too (run.admission)
    starved = [n for n in notes if n.startswith('run again: its first run was starved')]
    assert len(workers) == 2 + len(starved) and workers[0] != workers[1], teacher
    assert notes == starved + [lost], notes
    assert not any(n.startswith('run again') for n in run['notes'])


def test_a_worker_of_another_version_is_refused(cluster):
    with open(str(cluster['base'] / 'w3.log'), 'w') as log:
        odd = start_worker(cluster['address'], 1, log, EXP2_GRADER_VERSION='9.9.9')
        try:
            workers_up(cluster['address'], len(cluster['workers']) + 1)
            out = str(cluster['base'] / 'versions')
            proc = grade(cluster, out, '--only', 'cpp_broken')
        finally:
            os.killpg(odd.pid, signal.SIGKILL)
    assert proc.returncode == 0, proc.stdout[-3000:]
    assert 'has exp_assignment2 9.9.9, the teacher 0.1.0: refused' in proc.stdout


def test_an_unreachable_scheduler_is_one_line_fast(tmp_path):
    started = time.monotonic()
    proc = subprocess.run(['/usr/bin/python3', os.path.join(REPO, 'scripts', 'grade.py'),
                           os.path.join(HERE, 'fixtures', 'grading', 'base'),
                           '--out', str(tmp_path / 'out'),
                           '--scheduler', 'tcp://127.0.0.1:%d' % free_port()],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=60)
    # no hang: the connect timeout is 5 s; the bound leaves room for the grader's own
    # imports on a machine busy with other tests (11.5 s under CI's three workers)
    assert time.monotonic() - started < 30
    assert proc.returncode == 3
    lines = [l for l in proc.stdout.splitlines() if l.strip()]
    assert len(lines) == 1 and 'cannot reach the Dask scheduler at tcp://127.0.0.1:' in lines[0]


def _teacher(cluster, out, duration):
    """The teacher's grade of works and idle, once a run is going on a worker."""
    teacher = subprocess.Popen(['/usr/bin/python3', os.path.join(REPO, 'scripts', 'grade.py'),
                                cluster['folder'], '--out', out, '--scheduler',
                                cluster['address'], '--duration', duration, '--only', 'works',
                                'idle'], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               universal_newlines=True)
    deadline = time.monotonic() + 300
    while not any(sandboxes_of(w.pid) for w in cluster['workers']):
        assert time.monotonic() < deadline, 'no run started'
        time.sleep(0.5)
    return teacher


def test_ctrl_c_once_lets_the_running_runs_finish_and_records_them(cluster):
    out = str(cluster['base'] / 'interrupted-once')
    teacher = _teacher(cluster, out, '25')
    teacher.send_signal(signal.SIGINT)
    output, _ = teacher.communicate(timeout=300)
    assert teacher.returncode == 130, output[-2000:]
    assert 'Ctrl-C: no new run starts' in output
    recorded = [name for name in ('works', 'idle')
                if os.path.exists(os.path.join(out, 'runs', name, 'record', 'run.json'))]
    assert recorded, output[-2000:]
    for name in recorded:
        run, _ = records(out, name)
        assert run['ended_by'] == 'duration' and run['verdict'] == \
            grading_fixtures.EXPECTED[name]


def test_ctrl_c_twice_leaves_no_run_behind(cluster):
    out = str(cluster['base'] / 'interrupted')
    teacher = _teacher(cluster, out, '60')
    teacher.send_signal(signal.SIGINT)
    time.sleep(1)
    teacher.send_signal(signal.SIGINT)
    output, _ = teacher.communicate(timeout=60)
    assert teacher.returncode == 130, output[-2000:]
    assert not os.path.exists(os.path.join(out, 'runs', 'works', 'record', 'run.json'))
    deadline = time.monotonic() + 20
    while any(sandboxes_of(w.pid) for w in cluster['workers']):
        assert time.monotonic() < deadline, 'a run is still going on a worker'
        time.sleep(0.5)


def test_a_teacher_killed_leaves_no_run_behind_on_the_workers(cluster):
    """The scheduler releases what a client that is gone wanted: a worker
    ends the run its teacher's side no longer wants."""
    teacher = _teacher(cluster, str(cluster['base'] / 'teacher-killed'), '60')
    teacher.kill()
    teacher.wait()
    deadline = time.monotonic() + 30
    while any(sandboxes_of(w.pid) for w in cluster['workers']):
        assert time.monotonic() < deadline, 'a run is still going on a worker'
        time.sleep(0.5)


def test_a_run_whose_workers_keep_dying_is_a_grader_error(cluster):
    """Past the scheduler's allowed failures (Dask's default, 3), the run ends as the
    grader's fault."""
    logs = [open(str(cluster['base'] / ('dying%d.log' % i)), 'w') for i in range(3)]
    extra = [start_worker(cluster['address'], 1, log) for log in logs]
    try:
        workers_up(cluster['address'], len(cluster['workers']) + 3)
        out = str(cluster['base'] / 'dying')
        teacher = subprocess.Popen(['bash', RUN, 'grade', cluster['folder'], '--out', out,
                                    '--scheduler', cluster['address'], '--duration', '25',
                                    '--only', 'works'], stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, universal_newlines=True)
        killed = 0
        deadline = time.monotonic() + 600
        while teacher.poll() is None:
            assert time.monotonic() < deadline, 'the grading did not end'
            for worker in cluster['workers'] + extra:
                if worker.poll() is None and sandboxes_of(worker.pid):
                    os.killpg(worker.pid, signal.SIGKILL)
                    worker.wait()
                    killed += 1
            time.sleep(0.3)
        output = teacher.stdout.read()
        # the report is written; exit 4 says a run could not be graded (grade it again)
        assert teacher.returncode == 4, output[-3000:]
        assert "not graded, through a fault of the grader's" in output
        run, teacher = records(out, 'works')
        assert killed == 4
        assert run['verdict'] == 'grader_error'
        assert run['reason'].startswith('the grader lost this run: '), run['reason']
        assert run['lost'] and len(teacher['workers']) == 4
    finally:
        for proc in extra:
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGKILL)
        for log in logs:
            log.close()

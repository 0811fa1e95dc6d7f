"""A student's thread that never waits is found as the run runs, moved where it
takes only what CPU the others leave, and the run counted at
spinning.ELASTIC cores for it (run.spinning, run.cpu.Pace, admission.cost)."""
import os
import subprocess
import sys
import textwrap
import time

import pytest

from exp_assignment2.grading.run import admission, cpu, spinning

# one thread spins, one sleeps; it prints both thread ids and waits
PROGRAM = textwrap.dedent('''
    import sys, threading, time
    def spin():
        while True:
            pass
    def rest():
        while True:
            time.sleep(0.05)
    ids = []
    for target in (spin, rest):
        thread = threading.Thread(target=target, daemon=True)
        thread.start()
        ids.append(thread.native_id)
    print(*ids, flush=True)
    time.sleep(600)
''')


@pytest.fixture
def spinner(tmp_path):
    """A process (argv[0] ``name``) with a spinning and a sleeping thread: (pid, spin, rest)."""
    procs = []

    def start(name='scripts/student_node.py'):
        script = tmp_path / name
        script.parent.mkdir(parents=True, exist_ok=True)
        script.write_text(PROGRAM)
        proc = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
        procs.append(proc)
        spin, rest = (int(v) for v in proc.stdout.readline().split())
        return proc.pid, spin, rest
    yield start
    for proc in procs:
        proc.kill()
        proc.wait()


class Group(object):
    """A stand-in group: what was moved in."""

    def __init__(self, ok=True):
        self.moved, self.ok = [], ok

    def add(self, tid):
        self.moved.append(tid)
        return self.ok


def look_twice(spinners, pids, wall=1.5):
    spinners.look(pids, time.monotonic())
    time.sleep(wall)
    return spinners.look(pids, time.monotonic())


def test_the_thread_that_never_waits_is_found_and_moved_the_sleeping_one_is_not(spinner):
    pid, spin, rest = spinner()
    group = Group()
    spinners = spinning.Spinners(group)
    table = look_twice(spinners, [pid])
    assert group.moved == [spin]
    assert set(spinners.found) == {spin}
    assert spinners.found[spin]['program'] == 'student_node.py'     # no path of this machine
    assert 'student_node.py looped without waiting' in spinning.note(spinners.found.values())
    assert rest in table and table[spin][1] > table[rest][1]
    assert spinners.counted(table) == pytest.approx(spinning.ELASTIC)
    assert spinners.cpu_s(table) == pytest.approx(table[spin][1])


def test_the_simulator_ros_and_the_grader_are_never_moved(spinner):
    pids = [spinner(name)[0] for name in ('rosmaster', 'scripts/simulator.py')]
    group = Group()
    look_twice(spinning.Spinners(group), pids)
    assert group.moved == []


def test_a_thread_that_cannot_be_moved_is_counted_at_what_it_uses(spinner):
    pid, spin, rest = spinner()
    group = Group(ok=False)
    spinners = spinning.Spinners(group)
    table = look_twice(spinners, [pid])
    assert group.moved == [spin] and not spinners.found
    assert spinners.counted(table) == 0


def _cpu_v1():
    return spinning._own_cgroup_v1('cpu') is not None and os.geteuid() == 0


@pytest.mark.skipif(not _cpu_v1(), reason='needs root and the cgroup v1 cpu controller')
def test_the_group_takes_the_thread_at_a_low_weight_and_goes_with_the_run(spinner):
    pid, spin, rest = spinner()
    group = spinning.SpinGroup('a/b..c')      # a student's folder's name: no path in it
    assert group.add(spin), group.error
    assert os.path.dirname(group.directory) == os.path.normpath(spinning._own_cgroup_v1('cpu'))
    assert os.path.basename(group.directory).startswith('exp2-grade-spin_a_b_c-')
    with open(os.path.join(group.directory, 'cpu.shares')) as f:
        assert int(f.read()) == spinning.SHARES
    with open(os.path.join(group.directory, 'tasks')) as f:
        assert [int(t) for t in f.read().split()] == [spin]     # the thread, not its process
    os.kill(pid, 9)
    os.waitpid(pid, 0)
    group.remove()
    assert not os.path.exists(group.directory)


def test_the_pace_counts_a_spinner_at_elastic_cores_not_at_what_it_used(monkeypatch):
    """1.6 CPU s per simulated s, of which the spinning thread's 1.0: 0.6 + ELASTIC."""
    clock = {'t': 0.0}
    # tid 7 spins from the start (ready all the time, on a CPU all of it)
    monkeypatch.setattr(spinning, 'threads', lambda pids: {
        7: (1, 1.0 * clock['t'], 1.0 * clock['t']), 8: (1, 0.1 * clock['t'], 0.2 * clock['t'])})
    monkeypatch.setattr(cpu, 'snapshot', lambda pids: ({'student': 1.6 * clock['t']}, {}))
    monkeypatch.setattr(spinning, 'describe', lambda pid, tid: {'program': 'x', 'node': '', 'thread': 'y'})
    group = Group()
    pace = cpu.Pace(spinning.Spinners(group))
    costs = []
    for t in (20.0, 30.0, 40.0, 50.0):
        clock['t'] = t
        costs.append(pace.look([1], t, t))
    assert costs[0] is None                     # the base
    assert group.moved == [7]                   # found at the next look, and counted so
    assert costs[1:] == [pytest.approx(0.6 + spinning.ELASTIC)] * 3


def test_a_finished_run_costs_what_its_threads_that_spun_are_counted_at():
    result = {'cpu_s': {'student': 300.0, 'simulator': 60.0}, 'truth': {'sim_time': 200.0},
              'spinning': {'threads': [{'program': 'x', 'node': '', 'thread': 'y'}], 'cpu_s': 180.0,
                           'counted': 0.3}}
    assert admission.cost(result) == pytest.approx((360.0 - 180.0) / 200.0 + 0.3)
    del result['spinning']
    assert admission.cost(result) == pytest.approx(1.8)

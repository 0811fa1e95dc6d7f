"""A run's monitor (exp_assignment2.grading.run.monitor) does what
run.ending.end_reason says, and decides no end of its own: a stand-in driver
(a small Python process speaking the driver's events) in a stand-in sandbox,
no ROS, no bubblewrap."""
import subprocess
import sys
import time

from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.plan.spec import RunSpec
from exp_assignment2.grading.run import monitor
from exp_assignment2.grading.run.runner import Run, RunSettings

BUILT = 'print(\'{"event": "built", "rc": %d}\', flush=True)\n'
# the driver's answer to "stop": it ends its commands and says so
STOPS = ('import sys\nfor line in sys.stdin:\n'
         '    if line.strip() == "stop":\n'
         '        print(\'{"event": "stopping"}\', flush=True)\n'
         '        break\n')


class Groups(object):
    notes = []

    def peak_memory(self):
        return 0

    def oom_killed(self):
        return False

    def pids(self):
        return []

    def remove(self):
        pass


class Box(object):
    """A sandbox that starts ``script`` as the driver."""

    def __init__(self, script):
        self.script, self.groups, self.proc = script, Groups(), None

    def start(self, command, stdout):
        self.proc = subprocess.Popen([sys.executable, '-c', self.script], stdin=subprocess.PIPE,
                                     stdout=stdout, text=True, bufsize=1)
        return self.proc

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait()
        return True


class Truth(object):
    latest, states, frames, topics, dropped, simulator, refused = None, 0, 0, {}, 0, None, []

    def real_time_factor(self):
        return None

    def close(self):
        pass


def watched(tmp_path, script, cancel=False):
    """(the run's result, wall s) of a run whose driver is ``script``."""
    profile = profiles.load('dog')
    spec = RunSpec(name='ann', path=str(tmp_path), kind='dir', profile=profile, duration=10.0)
    run = Run(RunSettings(profile, str(tmp_path / 'runs')), spec)
    run._fresh_dirs()
    if cancel:
        run.stop_event.set()
    result, started = {}, time.monotonic()
    monitor.watch(run, Box(script), Truth(), 'plan.json', 1.0, result)
    return result, time.monotonic() - started


def test_a_driver_that_ends_by_itself_ends_the_run_at_once(tmp_path):
    result, took = watched(tmp_path, BUILT % 0)
    assert result['ended_by'] == 'driver_exit' and result['sandbox_exit'] == 0
    assert result['build'] == {'rc': 0, 'error': None} and took < 10


def test_a_failed_build_ends_the_run_at_once_without_asking(tmp_path):
    result, took = watched(tmp_path, BUILT % 1 + 'import time\ntime.sleep(60)\n')
    assert result['ended_by'] == 'build_failed' and 'cpu_s' not in result
    assert result['sandbox_exit'] != 0 and took < 30       # killed, not waited for


def test_a_cancelled_run_is_killed_at_once_without_asking(tmp_path):
    """Ctrl-C twice: the teacher wants the runs stopped now (their records are not kept)."""
    result, took = watched(tmp_path, BUILT % 0 + 'import time\ntime.sleep(60)\n', cancel=True)
    assert result['ended_by'] == 'cancelled' and 'cpu_s' not in result
    assert result['sandbox_exit'] != 0 and took < 30       # killed, not waited for


def test_a_run_asked_to_stop_waits_for_its_driver(tmp_path, monkeypatch):
    """Any other end asks the driver to end its commands, and waits for it."""
    from exp_assignment2.grading.run import ending
    monkeypatch.setattr(ending, 'end_reason', lambda facts, now: 'duration')
    result, took = watched(tmp_path, BUILT % 0 + STOPS)
    assert result['ended_by'] == 'duration' and result['ended_at'] == 0.0
    assert 'cpu_s' in result and result['sandbox_exit'] == 0     # it ended by itself
    assert [e['event'] for e in result['events']] == ['built', 'stopping'] and took < 30

"""The grading's loop (exp_assignment2.grading.run.dispatch.grade) when the
teacher stops it or starts it again, with a stand-in cluster whose runs end
when the test says: Ctrl-C once, no new run starts and the running ones are
recorded; twice, they are stopped now and not kept; a resumed grading sends
no run it keeps. No ROS, no sandbox, no Dask scheduler."""
import os
import signal
import tempfile

import pytest

distributed = pytest.importorskip('distributed')
from exp_assignment2.grading import record  # noqa: E402
from exp_assignment2.grading.plan import profiles  # noqa: E402
from exp_assignment2.grading.plan.spec import RunSpec  # noqa: E402
from exp_assignment2.grading.run import dispatch, tasks  # noqa: E402
from exp_assignment2.grading.run.runner import Run, RunSettings  # noqa: E402
from exp_assignment2.grading.run.stopping import NO_NEW, NOW, Stopping  # noqa: E402


class Future(object):
    def __init__(self, label):
        self.label, self.outcome = label, None

    def done(self):
        return self.outcome is not None

    def result(self):
        return self.outcome


def came_back(name, label, **fields):
    """What a worker sends back: the run's directory with its record."""
    run = tempfile.mkdtemp()
    record.write(os.path.join(run, 'record'), record.RunRecord.new(
        name, label, 1, verdict='passed', reason='', run_id=label * 4, **fields))
    return {'archive': tasks.pack_run(run)[0], 'cut': []}


class Cluster(object):
    """Runs start in the order sent, ``slots`` at once; ``step()`` ends the
    oldest running one, as its worker would (a run stopped now: cancelled)."""
    version = '0.1.0'

    def __init__(self, slots=1):
        self.slots, self.started, self.futures = slots, {}, []
        self.sent, self.cancelled, self.no_new, self.stopped_now = [], [], False, False
        self.paces, self.ending = {}, set()     # none told: each run at its estimate

    def submit(self, payload):
        self.sent.append(payload['label'])
        future = Future(payload['label'])
        future.name = payload['spec']['name']
        self.futures.append(future)
        return future

    def poll_starts(self):
        running = [f for f in self.futures if f.label in self.started and not f.done()]
        for future in self.futures:
            if len(running) >= self.slots or self.no_new:
                break
            if future.label not in self.started and future not in self.cancelled:
                self.started[future.label] = ['tcp://worker:1']
                running.append(future)

    def step(self):
        for future in self.futures:
            if future.label in self.started and not future.done():
                future.outcome = came_back(future.name, future.label, ended_by=(
                    'cancelled' if self.stopped_now else 'duration'))
                return

    def stop_starting(self, labels, before=None):
        self.no_new = True
        waiting = [f for f, label in labels.items()
                   if len(self.started.get(label) or []) <= (before or {}).get(label, 0)]
        self.cancelled += waiting
        return waiting

    def stop_now(self):
        self.no_new = self.stopped_now = True
        self.step()

    def cancel(self, futures):
        self.cancelled += list(futures)

    def worker_count(self):
        return 1


class Progress(object):
    total = 0

    def __init__(self, cluster, stopping, at):
        self.cluster, self.stopping, self.at, self.shown, self.said = cluster, stopping, at, 0, []

    def show(self, runs):
        """Each look of the loop: the teacher presses Ctrl-C at the looks ``at``."""
        self.shown += 1
        self.stopping.asked += self.at.count(self.shown)
        if self.shown % 2 == 0:
            self.cluster.step()

    def line(self, text):
        self.said.append(text)


def runs_of(tmp_path, names):
    profile = profiles.load('dog')
    settings = RunSettings(profile, str(tmp_path / 'runs'))
    return [Run(settings, RunSpec(name=n, path=str(tmp_path / n), kind='dir', profile=profile))
            for n in names]


@pytest.fixture
def no_wait(monkeypatch):
    monkeypatch.setattr(distributed, 'wait', lambda *args, **kwargs: None)
    monkeypatch.setattr(tasks, 'pack_submission', lambda submission, copies: ('tar', b''))


def test_ctrl_c_once_starts_no_new_run_and_records_the_running_one(tmp_path, no_wait):
    cluster, stopping = Cluster(), Stopping()
    runs = runs_of(tmp_path, ['ann', 'ben', 'cat'])
    progress = Progress(cluster, stopping, at=[1])
    stopped = dispatch.grade(runs, cluster, progress, None, stopping)
    assert [r.label for r in stopped] == ['ben', 'cat']
    assert {r.label: r.state for r in runs} == {'ann': 'done', 'ben': 'stopped',
                                                'cat': 'stopped'}
    assert record.load(runs[0].record)['verdict'] == 'passed'
    assert not os.path.exists(runs[1].record)
    assert progress.said == ['Ctrl-C: no new run starts; the running ones (1) finish and '
                             'are recorded (Ctrl-C again: stop them now)']


def test_ctrl_c_twice_stops_the_running_ones_and_keeps_no_record_of_them(tmp_path, no_wait):
    cluster, stopping = Cluster(slots=2), Stopping()
    runs = runs_of(tmp_path, ['ann', 'ben', 'cat'])
    progress = Progress(cluster, stopping, at=[1, 1])
    stopped = dispatch.grade(runs, cluster, progress, None, stopping)
    assert cluster.stopped_now and [r.label for r in stopped] == ['ann', 'ben', 'cat']
    assert not any(os.path.exists(r.dir) for r in runs)
    assert progress.said == ['Ctrl-C again: stopping the running ones (2) now']
    # cat never started; ann ended at once (cancelled: no record), ben not in time
    assert [f.label for f in cluster.cancelled] == ['cat', 'ben']


def test_a_resumed_grading_sends_only_what_it_does_not_keep(tmp_path, no_wait):
    from exp_assignment2.grading.entry.copies import Copies
    from exp_assignment2.grading.run.resume import Resume
    for name in ('ann', 'ben'):
        os.makedirs(str(tmp_path / name))
    first = Cluster(slots=2)
    with Copies() as copies:
        runs = runs_of(tmp_path, ['ann', 'ben'])
        dispatch.grade(runs, first, Progress(first, Stopping(), at=[]), copies,
                       resume=Resume(str(tmp_path / 'runs'), copies, log=lambda line: None))
        ids = {r.label: record.load(r.record)['run_id'] for r in runs}
        record.unfinish(runs[1].record)         # killed before ben's record was whole
        again, said = Cluster(slots=2), []
        runs = runs_of(tmp_path, ['ann', 'ben'])
        dispatch.grade(runs, again, Progress(again, Stopping(), at=[]), copies,
                       resume=Resume(str(tmp_path / 'runs'), copies, log=said.append))
    assert again.sent == ['ben'] and said == ['resuming: 1 run kept, 1 to run (1 not finished)']
    assert record.load(runs[0].record)['run_id'] == ids['ann']


def test_the_signals_are_counted_and_a_third_ctrl_c_leaves_at_once():
    with Stopping() as stopping:
        os.kill(os.getpid(), signal.SIGINT)
        assert stopping.asked == NO_NEW
        os.kill(os.getpid(), signal.SIGINT)
        assert stopping.asked == NOW
        with pytest.raises(KeyboardInterrupt):
            os.kill(os.getpid(), signal.SIGINT)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    with Stopping() as stopping:
        os.kill(os.getpid(), signal.SIGTERM)
        assert stopping.asked == NOW


NOTICED = {}


def _until_unwanted(token):
    """A task as a run's watcher is: until the teacher's side no longer wants it."""
    import time
    from exp_assignment2.grading.run.cluster import _wanted
    worker = distributed.get_worker()
    key = worker.get_current_task()
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        if not _wanted(worker, key):
            NOTICED[token] = True
            return
        time.sleep(0.2)


def test_a_task_the_teacher_no_longer_wants_is_seen_so_by_its_worker():
    """Its future cancelled (and so when the teacher's client is gone: the
    scheduler releases what it wanted): the worker's run ends."""
    import time
    cluster = distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                       dashboard_address=None)
    try:
        with distributed.Client(cluster) as client:
            future = client.submit(_until_unwanted, 'one', pure=False)
            time.sleep(1.0)         # running
            assert 'one' not in NOTICED
            client.cancel([future])
            deadline = time.monotonic() + 10
            while 'one' not in NOTICED:
                assert time.monotonic() < deadline, 'the task did not see it was cancelled'
                time.sleep(0.1)
    finally:
        cluster.close()

"""The grader's runs as Dask tasks, on one machine or many (no ROS).

One code path: by default an in-process local cluster with ``--jobs`` slots;
with ``--scheduler tcp://HOST:PORT``, that scheduler's workers (``bash
tools/run grade-worker``). Each task asks for one ``runs`` resource, so a
worker started with ``--resources runs=K`` takes at most K runs at once.

* A worker whose package version is not the teacher's is left out (one line
  naming both versions), and refuses a run that reaches it anyway.
* A worker lost in the middle of a run: Dask runs the task again on another
  worker; each start is announced on a Dask queue, so the report says which
  runs were run again and where. When the scheduler's ``allowed-failures``
  (Dask's default: 3) is passed, at the fourth loss, the run
  ends as ``grader_error`` (KilledWorker), never as the student's fault.
* Ctrl-C (or SIGTERM) sets a Dask event that every running task polls: its
  run is ended at once (its sandbox killed), and the futures are cancelled.
"""
import shutil
import socket
import time
import uuid
import warnings

from exp_assignment2.grading import record
from exp_assignment2.grading.judge import verdicts
from exp_assignment2.grading.run import ending
from exp_assignment2.grading.run import tasks
from exp_assignment2.grading.run.dask_settings import QUIET_LOCAL

CONNECT_TIMEOUT = 5.0          # s to reach a scheduler, then one line
# the grading's Dask names, each with the grading's token
STOP, NO_NEW, STARTS = 'exp2-grade-stop-', 'exp2-grade-no-new-', 'exp2-grade-starts-'


class ClusterError(Exception):
    """One line: the scheduler cannot be reached, or no worker can take runs."""


def _check_reachable(address, timeout=CONNECT_TIMEOUT):
    """A plain TCP connection first: Dask's own can take much longer to give up."""
    hostport = address.split('://', 1)[-1]
    host, _, port = hostport.rpartition(':')
    try:
        with socket.create_connection((host or 'localhost', int(port)), timeout=timeout):
            return
    except (OSError, ValueError) as exc:
        raise ClusterError('cannot reach the Dask scheduler at %s: %s' % (
            address, getattr(exc, 'strerror', None) or exc))


def _remote_version():
    return tasks.package_version()


def _wanted(worker, key):
    """The teacher's side still wants the task: it neither cancelled it nor
    went away (killed: the scheduler then releases its tasks, and the worker
    marks the one it runs cancelled)."""
    state = getattr(worker, 'state', worker)
    task = getattr(state, 'tasks', {}).get(key) if key else True
    return task is True or (task is not None and
                            task.state not in ('cancelled', 'released', 'forgotten'))


def _task(payload, data, token):
    """What a worker runs: announce the start; none once the teacher said no
    new run starts (Ctrl-C once); else run, until the teacher's stop (Ctrl-C
    twice) or until the teacher's side no longer wants it."""
    from distributed import Event, Queue, get_worker
    payload = dict(payload, data=data)
    worker = get_worker()
    key = getattr(worker, 'get_current_task', lambda: None)()
    starts = Queue(STARTS + token)
    starts.put({'label': payload['label'], 'worker': worker.address,
                'attempt': payload.get('attempt') or 1, 'time': time.time()})
    if Event(NO_NEW + token).is_set():      # after the announcement: see Cluster.stop_starting
        return {'skipped': True}
    stop = Event(STOP + token)
    return tasks.run_task(payload, stop=lambda: stop.wait(1.0) or not _wanted(worker, key),
                          report=lambda news: starts.put(dict(news, label=payload['label'])))


class Cluster(object):
    """A Dask client for grading: ``submit`` runs, ``poll`` for progress, ``close``."""

    def __init__(self, scheduler=None, jobs=1, log=print):
        import dask
        from distributed import Client, LocalCluster
        self.log = log
        # allowed-failures is the scheduler's own setting: Dask's default (3) here too
        dask.config.set({'distributed.comm.timeouts.connect': '%ds' % CONNECT_TIMEOUT})
        self.local = None
        if scheduler:
            _check_reachable(scheduler)
            try:
                self.client = Client(scheduler, timeout=CONNECT_TIMEOUT)
            except (OSError, TimeoutError) as exc:
                raise ClusterError('cannot reach the Dask scheduler at %s: %s'
                                   % (scheduler, exc))
            dashboard = self.client.dashboard_link
            if dashboard:
                log('Dask dashboard: %s' % dashboard)
        else:
            dask.config.set(QUIET_LOCAL)
            self.local = LocalCluster(n_workers=1, threads_per_worker=jobs, processes=False,
                                      resources={'runs': jobs}, dashboard_address=None)
            self.client = Client(self.local)
        self.token = uuid.uuid4().hex[:12]
        from distributed import Event, Queue
        self.stop_event = Event(STOP + self.token, client=self.client)
        self.no_new = Event(NO_NEW + self.token, client=self.client)
        self.starts = Queue(STARTS + self.token, client=self.client)
        self.started = {}           # label -> [worker address, ...] (more than one: run again)
        self.attempts = {}          # label -> the attempt of each of those starts
        self.paces = {}             # label -> what its run costs as it runs, not yet read
        self.ending = set()         # labels of the runs ending, not yet read
        self.version = tasks.package_version()
        self.workers = self._eligible_workers()

    def _eligible_workers(self):
        """Addresses of the workers with the teacher's version (None: all, on one machine)."""
        if self.local is not None:
            return None
        versions = self.client.run(_remote_version)
        good = [w for w, v in versions.items() if v == self.version]
        for worker, version in sorted(versions.items()):
            if version != self.version:
                self.log('worker %s has exp_assignment2 %s, the teacher %s: refused'
                         % (worker, version, self.version))
        if not good:
            raise ClusterError('no worker with exp_assignment2 %s (workers: %s)' % (
                self.version, ', '.join('%s %s' % kv for kv in sorted(versions.items()))
                or 'none'))
        return good

    def worker_count(self):
        try:
            return len(self.client.scheduler_info()['workers'])
        except Exception:     # the scheduler went away: the progress line says 0
            return 0

    def submit(self, payload):
        # the submission's bytes stay in the task itself, held by the scheduler: a
        # copy scattered to one worker is lost with that worker, and the run with it
        payload = dict(payload)
        data = payload.pop('data')
        with warnings.catch_warnings():       # "Large object ... in task graph": on purpose
            warnings.simplefilter('ignore', UserWarning)
            return self._submit(payload, data)

    def _submit(self, payload, data):
        attempt = payload.get('attempt') or 1      # a starved run is sent again
        return self.client.submit(_task, payload, data, self.token, resources={'runs': 1},
                                  pure=False, workers=self.workers,
                                  allow_other_workers=False, key='grade-%s-%s%s' % (
                                      payload['label'], self.token,
                                      '-%d' % attempt if attempt > 1 else ''))

    def poll_starts(self):
        """Read the start announcements (what runs where, and which started again)
        and the running runs' paces (``paces``: CPU s per simulated s as they run)
        and ends (``ending``: their commands asked to end)."""
        for start in self.starts.get(batch=True):      # what is there now, without waiting
            if 'pace' in start:
                self.paces[start['label']] = start['pace']
            if start.get('ending'):
                self.ending.add(start['label'])
            if 'worker' not in start:
                continue
            self.started.setdefault(start['label'], []).append(start['worker'])
            self.attempts.setdefault(start['label'], []).append(start.get('attempt') or 1)

    def stop_starting(self, labels, before=None):
        """Ctrl-C once: no run starts from now on; of ``labels`` ({future: its
        run's label}), the futures of the runs that had not started,
        cancelled (``before``: label -> its starts of earlier attempts, a
        starved run sent again). A task looks at the event after announcing
        its start: its run was announced before the event was set, and runs
        on, or it does not run."""
        self.no_new.set()
        self.poll_starts()
        before = before or {}
        waiting = [f for f, label in labels.items()
                   if len(self.started.get(label) or []) <= before.get(label, 0)]
        self.client.cancel(waiting)
        return waiting

    def stop_now(self):
        """Ctrl-C twice: every running run ends at once, its sandbox killed
        (each task polls this event); their futures then return."""
        self.no_new.set()
        self.stop_event.set()

    def cancel(self, futures):
        self.stop_now()
        self.client.cancel(list(futures))

    def close(self):
        try:
            self.client.close()
        finally:
            if self.local is not None:
                self.local.close()


def payload(run, version, copies, attempt=1):
    """What a task needs to run one Run anywhere (see tasks.run_task): its
    specification as a plain dict, and the submission's bytes (packed from
    its copy in ``copies``, entry.copies.Copies); ``attempt`` 2 for a run
    sent again (run.admission: starved)."""
    kind, data = tasks.pack_submission(run.submission, copies)
    return {'spec': run.spec.to_dict(), 'packed_kind': kind, 'data': data,
            'label': run.label, 'version': version, 'attempt': attempt}


def _planned(run, teacher):
    """The teacher's part ``teacher``, with what the run was planned from
    (run.resume) when the teacher's side said it, and the teacher's side's
    notes on it (why it was run again)."""
    if run.planned is not None:
        teacher['planned'] = run.planned
    notes = list(getattr(run, 'notes', None) or [])
    if notes:
        teacher['notes'] = notes + list(teacher.get('notes') or [])
    return teacher


def lost_workers(workers, attempts=None):
    """Of the workers a run started on, in order, the indices of those lost in
    the middle of it: each start followed by another of the same attempt
    (Dask running the task again). A start of a later attempt (a starved run
    sent again) is no loss. ``attempts`` None: all one attempt."""
    attempts = list(attempts or [])
    attempts += [1] * (len(workers) - len(attempts))
    return [i for i in range(len(workers) - 1) if attempts[i] == attempts[i + 1]]


def unpack_result(outcome, run, started, attempts=None):
    """The run's directory on the teacher's side as its worker sent it back
    (its record as the worker wrote it), and the teacher's part added beside
    it: the workers that ran it (every attempt's), a note when a worker was
    lost, what was cut. ``attempts``: label -> the attempt of each start."""
    own = tasks.unpack_run(outcome['archive'], run.dir)
    if own is None:
        raise ValueError('its worker sent back no record')
    workers = list(started.get(run.label) or [])
    teacher = {'workers': workers}
    lost = lost_workers(workers, (attempts or {}).get(run.label))
    if lost:        # named with the worker that took the run over from the last of them
        teacher['notes'] = ['run again: its worker %s was lost in the middle of the run; '
                            'done on %s' % (', '.join(workers[i] for i in lost),
                                            workers[lost[-1] + 1])]
    teacher = _planned(run, teacher)
    if outcome.get('cut'):
        teacher['cut'] = list(outcome['cut'])
    result = record.write(run.record, own, teacher=teacher)     # its run.json last
    run.result, run.state = result, 'done'
    return result


def lost_result(run, error, started):
    """A run Dask gave up on (its workers kept dying): the grader's fault."""
    return not_run(run, started.get(run.label) or [], lost=(
        str(error).splitlines()[0][:300] if str(error) else type(error).__name__))


def not_run(run, workers=(), **told):
    """The record of a run that did not run on a worker, made on the teacher's
    side: ``told`` is why (one of judge.seen.TOLD: ``refused``, ``rejected``,
    ``lost``, ``grader_fault``), and the verdict table decides on it."""
    spec = run.spec
    record.unfinish(run.record)     # nothing of an earlier attempt beside this record
    shutil.rmtree(run.dir, ignore_errors=True)
    result = record.RunRecord.new(
        spec.name, run.label, run.seed, run_id=uuid.uuid4().hex, commands=spec.commands,
        commands_from=spec.commands_from, readme_commands=spec.readme_commands,
        truth={'sim_time': 0.0}, notes=list(spec.notes), duration=spec.duration,
        ended_by=ending.NOT_RUN, **told)
    if told.get('rejected'):        # what it holds, as far as it could be read
        result['packages'] = list(spec.packages)
    if spec.git:        # the commit a git repository was to be graded at (git_entries.py)
        result['git'] = spec.git
    result.update(verdicts.judge_told(result))
    result['teacher'] = _planned(run, {'workers': list(workers)})
    run.result, run.state = record.write(run.record, result), 'done'
    return run.result

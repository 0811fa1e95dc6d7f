"""The grading's runs sent to the cluster and received on the teacher's side
(no ROS): each run a Dask task, or, when it cannot be sent (refused,
rejected, not sendable), its record made here; each sent when the cores
it needs are free (run.admission, counting what the running ones cost as
they run), a starved one again after the others;
each run that comes back
unpacked with the teacher's part of its record, or lost; a run whose checks
failed in a release it was not told run again in the next; a run a
resumed grading keeps (run.resume) not sent at all; Ctrl-C (run.stopping).
"""
import shutil

from exp_assignment2.grading import record
from exp_assignment2.grading.plan.spec import RunSpec
from exp_assignment2.grading.run import tasks
from exp_assignment2.grading.run.admission import STARVED_NOTE, Admission, starved
from exp_assignment2.grading.run.cluster import lost_result, not_run, payload, unpack_result
from exp_assignment2.grading.run.runner import Run
from exp_assignment2.grading.run.stopping import NO_NEW, Stopping

STOP_WAIT = 30.0        # s the runs stopped now have to end (their sandboxes killed)


def in_next_release(run):
    """The run again in the next ROS release whose plugins behave otherwise
    for it, when it ran in a release it was not told and the run shows the
    release was wrong for it (judge.steering: it turned away from the ball it
    saw, or went nowhere with its drive commanded, or failed to look a frame
    up): its checks failed, or passed with those the wrong release gave no
    occasion not judged; None: no other to try, or nothing points at the
    release (a failure of its own fails the same in any). The decision is kept in the
    run's teacher part (``release_next``). ros_release.py; the better run counts
    (report.py)."""
    spec, result = run.spec, run.result or {}
    verdict = result.get('verdict')
    if not spec.releases_next or verdict not in ('failed_checks', 'passed'):
        return None
    release = spec.releases_next[0]
    evidence = result.get('release_evidence') or {}
    # a failed run of an older record (no evidence) is tried, as before; a passed one
    # only where its run shows the release was wrong (checks not judged for it)
    tried = bool(evidence.get('release', verdict == 'failed_checks'))
    if verdict == 'passed' and not tried:
        return None
    _keep_decision(run, {'release': release, 'tried': tried,
                         'why': evidence.get('why') or 'no evidence of the run was read'})
    if not tried:
        return None
    data = spec.to_dict()
    data.update(release=release, releases_next=data['releases_next'][1:],
                label='%s-%s' % (spec.label, release),
                release_why='%s in ROS %s (%s): run again in %s, whose Gazebo plugins '
                            'behave otherwise for it (%s)' % (
                                'its checks failed' if verdict == 'failed_checks' else
                                'it passed, some checks not judged,', spec.release,
                                spec.release_why, release,
                                evidence.get('why') or 'the run was not read'))
    return Run(run.settings, RunSpec.from_dict(data))


def _keep_decision(run, decision):
    """The next release's decision in the run's teacher part (its page says it)."""
    try:
        kept = record.load(run.record) or {}
        teacher = dict(kept.get('teacher') or {}, release_next=decision)
        run.result = record.write(run.record, teacher=teacher)
    except OSError:
        pass


def grade(runs, cluster, progress, copies, stopping=None, resume=None, admission=None):
    """Every Run as a Dask task (its submission packed from its copy in
    ``copies``), but those ``resume`` keeps (run.resume: a finished run of
    the same plan), each sent when ``admission`` (run.admission) lets it
    start, and a starved one sent again once the others are done;
    ``stopping`` (run.stopping) says when the teacher stops it: once, no new
    run starts and the running ones are received; twice, they end now and
    are not kept. Returns the runs not run ([] when the grading went to its end)."""
    from distributed import wait
    stopping = stopping or Stopping()
    admission = admission or Admission(None, 1.0, len(runs) or 1)
    futures, todo = {}, []     # future -> its run; the runs run now (the progress line's)
    queued, starved_runs = [], []   # runs to send when admitted; starved ones, after the others

    def send(run, attempt=1):
        """The run as a Dask task (its future), or its grader_error (None)."""
        try:
            future = cluster.submit(payload(run, cluster.version, copies, attempt))
        except Exception as exc:      # noqa: BLE001 -- the grader's fault, this run's only
            not_run(run, grader_fault=record.fault('could not send it to a worker', exc))
            return None
        futures[future] = run
        run.starts_before = len(cluster.started.get(run.label) or [])   # an earlier attempt's
        pending.add(future)
        admission.started(run.label, run.settings.real_time_factor, run.spec.name)
        return future

    def admit():
        """Send what may start now: each queued run, in turn, that fits the cores
        free (a cheap one beside a dear one), then, once nothing else runs or
        waits, the starved ones, one at a time."""
        for run in list(queued):
            if stopping.asked:
                break
            if admission.may_start(run.settings.real_time_factor, run.spec.name):
                queued.remove(run)
                send(run)
        if starved_runs and not queued and not pending and not stopping.asked:
            run, factor = starved_runs.pop(0)
            run.notes = [STARVED_NOTE % factor]
            run.state = 'waiting'
            send(run, attempt=2)

    def start(run):
        """The run kept, or decided here (refused, rejected), or sent."""
        kept = resume.keep(run) if resume is not None else None
        if kept is not None:
            run.result, run.state = kept, 'done'
            admission.counted(kept, run.spec.name)      # what it cost counts from the start
            follow(run)
            return
        todo.append(run)
        if run.spec.refused:       # the teacher's file is wrong about it, or the grader failed
            not_run(run, refused=run.spec.refused)
        elif run.spec.rejected:    # nothing to run: it does not unpack, it holds no package
            not_run(run, rejected=run.spec.rejected)
        else:
            queued.append(run)

    def receive(run, future):
        _received(run, future, cluster)
        if admission.ended(run.label, run.result, run.spec.name) and run.state == 'done' and \
                not run.notes and not stopping.asked:
            starved_runs.append((run, starved(run.result)))
            return          # followed once run again
        if run.state == 'done':
            follow(run)

    def follow(run):
        """Its checks failed: as its student may have run it, in the next release."""
        again = in_next_release(run)
        if again is not None:
            runs.append(again)
            if stopping.asked:
                again.state = 'stopped'
            else:
                start(again)

    pending = set()
    for run in list(runs):
        start(run)
    if resume is not None:
        resume.say()
    progress.total = len(todo)
    noticed = 0
    admit()
    try:
        while pending:
            if stopping.asked > noticed:
                if not noticed:         # no new run starts (also before stopping them now)
                    for future in cluster.stop_starting(
                            {f: futures[f].label for f in pending},
                            {futures[f].label: futures[f].starts_before for f in pending}):
                        pending.discard(future)     # a starved one: its first record kept
                        futures[future].state = 'done' if futures[future].result else 'stopped'
                    for run in queued:
                        run.state = 'stopped'
                    del queued[:], starved_runs[:]    # a starved run keeps its first record
                noticed = stopping.asked
                if noticed == NO_NEW:
                    progress.line('Ctrl-C: no new run starts; the running ones (%d) finish '
                                  'and are recorded (Ctrl-C again: stop them now)' % len(pending))
                else:
                    progress.line('Ctrl-C again: stopping the running ones (%d) now'
                                  % len(pending))
                    cluster.stop_now()
                    _received_in_time(pending, futures, cluster, receive)
                    break
            cluster.poll_starts()
            while cluster.paces:        # what the running runs cost as they run
                admission.pace(*cluster.paces.popitem())
            while cluster.ending:       # and those that cost little from now on
                admission.ending(cluster.ending.pop())
            for future in [f for f in pending if f.done()]:
                pending.discard(future)
                receive(futures[future], future)
            admit()
            for future in pending:
                run = futures[future]
                if len(cluster.started.get(run.label) or []) > run.starts_before \
                        and run.state == 'waiting':
                    run.state = 'running'
            progress.total = len(todo)
            progress.show(todo)
            try:        # until a run ends, or half a second for the progress line
                wait(list(pending), timeout=0.5, return_when='FIRST_COMPLETED')
            except TimeoutError:
                pass
        if todo:
            progress.show(todo)
    except KeyboardInterrupt:       # a third Ctrl-C, or the grader's own end
        progress.line('ending every run')
        cluster.cancel(pending)
        raise
    return [run for run in runs if run.state != 'done']


def _received(run, future, cluster):
    """The run as its worker sent it back, recorded on the teacher's side; or
    its grader_error. A run that did not start (no new run starts) or that
    was stopped now (its record not kept) is left ``stopped``."""
    from concurrent.futures import CancelledError
    from distributed import KilledWorker
    cluster.poll_starts()
    try:
        outcome = future.result()
        if outcome.get('skipped'):
            run.state = 'stopped'
            return
        unpack_result(outcome, run, cluster.started, getattr(cluster, 'attempts', None))
    except (KilledWorker, CancelledError, tasks.VersionMismatch, OSError,
            RuntimeError) as exc:
        lost_result(run, exc, cluster.started)
    except Exception as exc:      # noqa: BLE001 -- this run's grader_error only
        not_run(run, cluster.started.get(run.label) or [],
                grader_fault=record.fault('failed with this run', exc))
    if (run.result or {}).get('ended_by') == 'cancelled':
        record.unfinish(run.record)         # stopped half way: run again by a resume
        shutil.rmtree(run.dir, ignore_errors=True)
        run.result, run.state = None, 'stopped'


def _received_in_time(pending, futures, cluster, receive):
    """The runs stopped now, waited for until they end (their sandboxes
    removed), at most STOP_WAIT s; the others' tasks cancelled."""
    from distributed import wait
    try:
        wait(list(pending), timeout=STOP_WAIT)
    except TimeoutError:
        pass
    for future in list(pending):
        if future.done():
            pending.discard(future)
            receive(futures[future], future)
        else:
            futures[future].state = 'stopped'
    cluster.cancel(pending)
    pending.clear()

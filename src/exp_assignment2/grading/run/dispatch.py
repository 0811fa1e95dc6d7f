"""The grading's runs sent to the cluster and received on the teacher's side
(no ROS): each run a Dask task, or, when it cannot be sent (refused,
rejected, not sendable), its record made here; each run that comes back
unpacked with the teacher's part of its record, or lost; a run whose checks
failed in a release it was not told run again in the next.
"""
from exp_assignment2.grading import record
from exp_assignment2.grading.plan.spec import RunSpec
from exp_assignment2.grading.run import tasks
from exp_assignment2.grading.run.cluster import lost_result, not_run, payload, unpack_result
from exp_assignment2.grading.run.runner import Run


def in_next_release(run):
    """The run again in the next ROS release whose plugins behave otherwise
    for it, when its checks failed in a release it was not told (None: no
    other to try). ros_release.py; the better run counts (report.py)."""
    spec, result = run.spec, run.result or {}
    if not spec.releases_next or result.get('verdict') != 'failed_checks':
        return None
    data = spec.to_dict()
    release = data['releases_next'][0]
    data.update(release=release, releases_next=data['releases_next'][1:],
                label='%s-%s' % (spec.label, release),
                release_why='its checks failed in ROS %s (%s): run again in %s, whose Gazebo '
                            'plugins behave otherwise for it' % (
                                spec.release, spec.release_why, release))
    return Run(run.settings, RunSpec.from_dict(data))


def grade(runs, cluster, progress, copies):
    """Every Run as a Dask task (its submission packed from its copy in
    ``copies``); Ctrl-C ends every run (on every worker) and returns."""
    from concurrent.futures import CancelledError
    from distributed import KilledWorker, wait
    version = cluster.version
    futures = {}

    def send(run):
        """The run as a Dask task (its future), or its grader_error (None)."""
        try:
            future = cluster.submit(payload(run, version, copies))
        except Exception as exc:      # noqa: BLE001 -- the grader's fault, this run's only
            not_run(run, grader_fault=record.fault('could not send it to a worker', exc))
            return None
        futures[future] = run
        return future
    for run in runs:
        if run.spec.refused:       # the teacher's file is wrong about it, or the grader failed
            not_run(run, refused=run.spec.refused)
        elif run.spec.rejected:    # nothing to run: it does not unpack, it holds no package
            not_run(run, rejected=run.spec.rejected)
        else:
            send(run)
    pending = set(futures)
    try:
        while pending:
            cluster.poll_starts()
            for future in [f for f in pending if f.done()]:
                pending.discard(future)
                run = futures[future]
                cluster.poll_starts()
                try:
                    unpack_result(future.result(), run, cluster.started)
                except (KilledWorker, CancelledError, tasks.VersionMismatch, OSError,
                        RuntimeError) as exc:
                    lost_result(run, exc, cluster.started)
                except Exception as exc:      # noqa: BLE001 -- this run's grader_error only
                    not_run(run, cluster.started.get(run.label) or [],
                            grader_fault=record.fault('failed with this run', exc))
                again = in_next_release(run)
                if again is not None:       # its checks failed: as its student may have run it
                    runs.append(again)
                    progress.total += 1
                    pending.update(f for f in [send(again)] if f is not None)
            for future in pending:
                run = futures[future]
                if run.label in cluster.started and run.state == 'waiting':
                    run.state = 'running'
            progress.show(runs)
            try:        # until a run ends, or half a second for the progress line
                wait(list(pending), timeout=0.5, return_when='FIRST_COMPLETED')
            except TimeoutError:
                pass
        progress.show(runs)
    except KeyboardInterrupt:
        progress.line('Ctrl-C: ending every run')
        cluster.cancel(pending)
        raise

"""The grader's Dask settings (no ROS): what a worker and the in-process cluster
of one machine leave out of their housekeeping (:mod:`.cluster`, :mod:`.worker`)."""


# A worker's housekeeping, for runs of minutes that no dashboard watches: Dask samples
# every thread's stack 100 times a second (its profiler), measures the machine every
# 0.5 s and the worker's memory every 0.1 s. On one machine that was 0.05 of a core
# beside the runs, all grading long.
QUIET_WORKER = {'distributed.worker.profile.enabled': False,
                'distributed.admin.system-monitor.interval': '5s',
                'distributed.worker.memory.monitor-interval': '1s'}
# and the in-process scheduler of one worker: nothing to steal, no one to tell its ticks
QUIET_LOCAL = dict(QUIET_WORKER, **{'distributed.scheduler.work-stealing': False,
                                    'distributed.admin.tick.interval': '500ms'})


def quiet_worker_environment():
    """:data:`QUIET_WORKER` as the environment a ``dask-worker`` reads it from."""
    return {'DASK_' + key.upper().replace('.', '__').replace('-', '_'): str(value)
            for key, value in QUIET_WORKER.items()}

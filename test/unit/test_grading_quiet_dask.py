"""The grader's Dask keeps no housekeeping a grading does not use: on one machine
the in-process worker neither profiles its threads nor steals work, and checks
the machine and its memory seldom; a ``grade-worker`` is started with the same."""
import json
import os
import subprocess
import sys

from exp_assignment2.grading.run import cluster, dask_settings

def test_the_local_worker_neither_profiles_nor_steals_and_looks_at_memory_seldom():
    grading = cluster.Cluster(jobs=1, log=lambda line: None)
    try:
        worker = list(grading.local.workers.values())[0]
        scheduler = grading.local.scheduler
        assert not {'profile', 'profile-cycle'} & set(worker.periodic_callbacks)
        assert 'stealing' not in scheduler.extensions
        assert worker.periodic_callbacks['memory_monitor'].callback_time == 1000
        assert worker.periodic_callbacks['monitor'].callback_time == 5000
    finally:
        grading.close()


def test_a_grade_worker_reads_the_same_settings_from_its_environment():
    keys = sorted(dask_settings.QUIET_WORKER)
    env = dict(os.environ, **dask_settings.quiet_worker_environment())
    read = subprocess.run(
        [sys.executable, '-c', 'import dask.config, json; print(json.dumps([dask.config.get(k) '
         'for k in %r]))' % keys], env=env, capture_output=True, text=True, check=True).stdout
    assert json.loads(read) == [dask_settings.QUIET_WORKER[k] for k in keys]

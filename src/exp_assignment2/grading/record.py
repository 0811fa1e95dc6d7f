"""A run's record (``RUN/record/run.json``): one writer, one reader (no ROS).

Like the CARLA leaderboard's route record: the runner, the cluster (a run
its workers lost, a run refused) and the report all handle one shape,
:class:`RunRecord`, written only by :func:`write` and read only by
:func:`load`/:func:`load_all`.

A record is a dict (it travels back from a Dask worker as one) with these
keys, those of a run that did not run left out:

* who: ``name``, ``label``, ``seed``, ``version``, ``profile``, ``workers``;
* what was asked: ``commands``, ``commands_from``, ``notes``, ``packages`` (every
  package of the submission: ``name``, ``rel``, ``built``, ``why``), ``duration``
  (the run's own simulated s), ``real_time_factor_asked``,
  ``repeat_command``, ``limits``, ``git`` (a git repository's commit graded, how it was
  chosen, the commits after it, days late and points off:
  :func:`exp_assignment2.grading.plan.git_entries.choose`);
* how it went: ``started``, ``finished``, ``events`` (the driver's), ``build``
  (the build's outcome as the driver sent it: ``rc`` and ``error`` with
  ``file``, ``line``, ``message``), ``ended_by`` (why the run was ended:
  :mod:`exp_assignment2.grading.run.ending`'s ``duration``,
  ``required_node_died``, ``all_exited``, ``wall_limit``, ``build_limit``,
  ``no_simulator``, ``disk_limit``, ``cancelled``; ``build_failed``,
  ``driver_exit`` when its driver ended first, ``not_run`` when it never
  started: not unpacked, no sandbox, refused or lost by the cluster),
  ``ended_at`` (the simulated s then), ``required_node`` (roslaunch's name of
  the required node whose death ended it), ``log_sizes``, ``truth``,
  ``real_time_factor``, ``wall_time``, ``cpu_s``, ``memory_mb``,
  ``peak_memory_mb``, ``oom``, ``all_gone``, ``sandbox_exit``, ``cut``;
* the verdict (:mod:`exp_assignment2.grading.judge.verdicts`): ``verdict``,
  ``reason``, ``checks`` (of a crashed or timed-out run too, with ``checks_until``
  naming its verdict: judged on the truth until its end; a check not run has ``judged``
  False and ``passed`` None), ``errors``, ``error_count``, ``died``, ``launch_errors``,
  ``roles`` (the robot, head, camera and ball judged, each with why:
  :mod:`exp_assignment2.grading.judge.roles`).
"""
import json
import os

NAME = 'run.json'


class RunRecord(dict):
    """One run's record (a dict of the keys above)."""

    @classmethod
    def new(cls, name, label, seed, **fields):
        return cls(dict(fields, name=name, label=label, seed=seed))

    def to_json(self):
        return json.dumps(self, indent=1, default=str)


def write(record_dir, record):
    """``record`` (a RunRecord, or a dict of its keys) as ``record_dir/run.json``; the record."""
    record = record if isinstance(record, RunRecord) else RunRecord(record)
    os.makedirs(record_dir, exist_ok=True)
    path = os.path.join(record_dir, NAME)
    with open(path + '.tmp', 'w') as f:
        f.write(record.to_json())
    os.replace(path + '.tmp', path)      # a reader never sees half of one
    return record


def load(record_dir):
    """The RunRecord in ``record_dir``, or None if it has none (or not JSON)."""
    try:
        with open(os.path.join(record_dir, NAME)) as f:
            data = json.load(f)
    except (OSError, ValueError):
        return None
    return RunRecord(data) if isinstance(data, dict) else None


def load_all(runs_dir):
    """[RunRecord] of every run directory of ``runs_dir`` that has one, by label."""
    if not os.path.isdir(runs_dir):
        return []
    found = (load(os.path.join(runs_dir, label, 'record'))
             for label in sorted(os.listdir(runs_dir)))
    return [r for r in found if r is not None]

"""A run's verdict decided on its facts, once when it ends and again from its
records (no ROS): ``grade --report-only`` with another profile (a threshold
raised, points moved, a check added that reads the recorded ground truth)
judges every run again from what its directory kept (the record, the ground
truth and frames under ``record/``, the logs under ``work/``), with no run
done again. The run's own record is never written again: what is judged
again goes to the report.
"""
import os

from exp_assignment2.grading import record
from exp_assignment2.grading.judge import verdicts
from exp_assignment2.grading.entry import build_deps

# what the verdict adds to a run's record (verdicts.judge), and nothing else
JUDGED = ('verdict', 'reason', 'errors', 'error_count', 'died', 'launch_errors', 'keyboard',
          'checks', 'checks_until', 'roles')
JUDGING_FAULT = 'failed while judging it'


def decide(work, record_dir, result, profile):
    """The verdict's fields put in ``result`` (the run's facts), decided by
    verdicts.RULES; a failure of the judging is the run's grader_fault."""
    try:
        result.update(verdicts.judge(work, record_dir, result, profile))
    except Exception as exc:      # noqa: BLE001 -- the grader's fault, this run's only
        result['grader_fault'] = record.fault(JUDGING_FAULT, exc)
        result.update(verdicts.judge_told(result))
    if result.get('verdict') == 'not_built':
        result['reason'] = build_deps.said_by_rosdep(result.get('reason') or '',
                                                     result.get('notes') or [])
    return result


def rejudged(run_dir, run, profile):
    """A copy of the record ``run`` of the run in ``run_dir``, judged again
    with ``profile``: its facts as recorded, its verdict's fields decided
    anew (a fault of an earlier judging is judged again too)."""
    facts = record.RunRecord({k: v for k, v in run.items() if k not in JUDGED})
    if (facts.get('grader_fault') or {}).get('what') == JUDGING_FAULT:
        del facts['grader_fault']
    return decide(os.path.join(run_dir, 'work'), os.path.join(run_dir, 'record'), facts,
                  profile)


def all_rejudged(runs_dir, runs, profile_of):
    """Every record of ``runs`` (those of ``runs_dir``) judged again, each
    with ``profile_of(name)`` (the profile, with grading.yaml's roles for
    that submission)."""
    return [rejudged(os.path.join(runs_dir, run['label']), run, profile_of(run['name']))
            for run in runs]

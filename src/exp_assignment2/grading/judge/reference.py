"""A reference solution's figures, from one of its runs (no ROS): what
``grade --calibrate`` turns into a profile's thresholds
(:mod:`~exp_assignment2.grading.plan.calibration`).

Two passes over the run's ground truth: first the distances the reference
keeps (:func:`distances`: where it stopped to look at the stopped ball, how
far it trailed the moving one, how far it turned its head), then, with the
settings made of them, the profile's own metrics on the same run
(:func:`figures`): what each check would give the reference, and when the
reference first showed each behaviour.
"""
import math

from exp_assignment2.grading.judge import ball_track as bt
from exp_assignment2.grading.judge import behaviours, metrics
from exp_assignment2.grading.judge.trace import NotJudged
from exp_assignment2.grading.plan.profile_keys import with_shared

SWEEP = 0.3          # rad: a head turned this far at a stop is looking around


def _percentile(values, share):
    values = sorted(values)
    if not values:
        return None
    return values[min(len(values) - 1, int(round(share * (len(values) - 1))))]


def distances(trace, roles, check):
    """{'stop_distances': [m from the ball where the head turned widest at each stop],
    'sweeps': [rad the head turned both ways at each stop], 'trailing': [m to the
    moving ball, the robot awake]}."""
    track = bt.samples(trace, roles.robot.name, roles.ball.name, roles.head.name,
                       check.get('arena'))
    speeds = bt.ball_speeds(track)
    asleep = behaviours._asleep(track, check)
    out = {'stop_distances': [], 'sweeps': [], 'trailing': []}
    for a, b in bt.stops(track, speeds, float(check.get('stop', 3.0))):
        heads = [(abs(s.head), k) for k, s in enumerate(track[a:b + 1], a) if s.head is not None]
        if not heads or max(heads)[0] < SWEEP:
            continue
        out['stop_distances'].append(round(bt.distance(track[max(heads)[1]]), 3))
        angles = [track[k].head for _, k in heads]
        out['sweeps'].append(round(min(max(angles), -min(angles)), 3))
    for i, s in enumerate(track):
        if speeds[i] is not None and speeds[i] >= bt.MOVING and i not in asleep:
            out['trailing'].append(round(bt.distance(s), 3))
    return out


def figures(trace, roles, profile):
    """{metric: (value, at) or None (not judged)} of the profile's checks on the
    run, and 'shown': the s by which every behaviour had been shown once
    (None: some never was)."""
    out, times = {}, []
    for check in profile['checks']:
        fn = metrics.METRICS[check['metric']]
        try:
            got = fn(trace, roles, with_shared(check, profile))
        except NotJudged:
            out[check['metric']] = None
            continue
        at = got[2] if len(got) > 2 else None
        out[check['metric']] = (got[0], at)
        if check['metric'] in behaviours.METRICS or check['metric'] == 'approaches':
            times.append(at)
    out['shown'] = None if None in times or not times else max(times)
    return out


def share_at(values, distance):
    """Share of ``values`` at or below ``distance`` (0 without values)."""
    return sum(v <= distance for v in values) / float(len(values)) if values else 0.0


def round_up(value, step):
    return math.ceil(value / step - 1e-9) * step


__all__ = ['distances', 'figures', 'share_at', 'round_up', '_percentile']

"""A reference solution's figures, from one of its runs (no ROS): what
``grade --calibrate`` turns into a profile's thresholds
(:mod:`~exp_assignment2.grading.plan.calibration`).

Two passes over the run's ground truth: first the distances the reference
keeps (:func:`distances`: where it came to rest at the ball to look around,
how far and how long it turned its head, how far it trailed the moving
ball), then, with the
settings made of them, the profile's own metrics on the same run
(:func:`figures`): what each check would give the reference, and the
shortest run in which it showed every behaviour (:func:`shown_by`).
"""
import math

from exp_assignment2.grading.judge import arrivals
from exp_assignment2.grading.judge import ball_track as bt
from exp_assignment2.grading.judge import behaviours, metrics
from exp_assignment2.grading.judge.trace import NotJudged
from exp_assignment2.grading.plan.profile_keys import with_shared

SWEEP = 0.3          # rad: a head turned this far each way after an arrival is looking around


def percentile(values, share):
    values = sorted(values)
    if not values:
        return None
    return values[min(len(values) - 1, int(round(share * (len(values) - 1))))]


def distances(trace, roles, check):
    """{'stop_distances': [m from the ball where it came to rest at each arrival after
    which it looked around], 'sweeps': [rad the head turned each way then, the lesser],
    'sweep_times': [s from the arrival to the head's second side],
    'trailing': [m to the moving ball while it was in view, the robot awake],
    'per_place': [s the ball was out of its sight for each place it wandered to],
    'asleep_after': [s it had been without the ball when each sleep began]}."""
    track = bt.samples(trace, roles.robot.name, roles.ball.name, roles.head.name,
                       check.get('arena'))
    speeds, sight = bt.ball_speeds(track), bt.Sight(trace, roles, check)
    asleep = behaviours._asleep(track, check)
    out = {'stop_distances': [], 'sweeps': [], 'sweep_times': [], 'trailing': [],
           'per_place': [], 'asleep_after': []}
    # each arrival's look is the head while the reference stayed there (it looks while
    # it rests): what it turned and how long it took, where it came to rest
    for i0, why, i1 in arrivals.arrivals(track, float('inf'), sight, asleep):
        during = [s for s in track[i0:i1 + 1] if s.head is not None]
        left = next((s.t for s in during if s.head >= SWEEP), None)
        right = next((s.t for s in during if s.head <= -SWEEP), None)
        if why is not None or left is None or right is None:
            continue
        out['stop_distances'].append(round(arrivals.settled_distance(track, i0, i1), 2))
        out['sweeps'].append(round(min(max(s.head for s in during),
                                       -min(s.head for s in during)), 3))
        out['sweep_times'].append(round(max(left, right) - track[i0].t, 1))
    for i, s in enumerate(track):
        if speeds[i] is not None and speeds[i] >= bt.MOVING and i not in asleep \
                and sight.sees(s):
            out['trailing'].append(round(bt.distance(s), 3))
    places, unseen, _ = behaviours.wandered(trace, roles, check)
    out['per_place'] = [round(unseen / len(places), 1)] if places else []
    # how long it had been without the ball when each sleep began
    for a, _, _, _ in behaviours.rests(track, check, float(check.get('rest', behaviours.REST))):
        seen_at = next((s.t for s in reversed(track[:a]) if sight.sees(s)), track[0].t)
        out['asleep_after'].append(round(track[a].t - seen_at, 1))
    return out


def figures(trace, roles, profile):
    """{metric: (value, at) or None (not judged)} of the profile's checks on the run."""
    out = {}
    for check in profile['checks']:
        try:
            got = metrics.METRICS[check['metric']](trace, roles, with_shared(check, profile))
        except NotJudged:
            out[check['metric']] = None
            continue
        out[check['metric']] = (got[0], got[2] if len(got) > 2 else None)
    return out


def shown_by(trace, roles, profile, step=10.0):
    """The shortest run (s, in ``step``s) in which the reference passed every check of
    its behaviours and its reach; None: not even the whole run."""
    wanted = [c for c in profile['checks']
              if c['metric'] in behaviours.METRICS or c['metric'] == 'approaches']
    t = step
    while t < trace.duration + step:
        head = metrics.Trace([s for s in trace.states if s['t'] <= t], trace.topics,
                             trace.errors, trace.models, trace.hello)
        results = metrics.evaluate(head, dict(profile, checks=wanted), roles)
        if all(r['passed'] for r in results):
            return min(t, trace.duration)
        t += step
    return None


def round_up(value, step):
    return math.ceil(value / step - 1e-9) * step



"""A reference solution's figures, from one of its runs (no ROS): what
``grade --calibrate`` turns into a profile's thresholds
(:mod:`~exp_assignment2.grading.plan.calibration`).

Two passes over the run's ground truth: first the distances the reference
keeps (:func:`distances`: where it stopped to look at the stopped ball, how
far it trailed the moving one, how far it turned its head), then, with the
settings made of them, the profile's own metrics on the same run
(:func:`figures`): what each check would give the reference, and the
shortest run in which it showed every behaviour (:func:`shown_by`).
"""
import math

from exp_assignment2.grading.judge import ball_track as bt
from exp_assignment2.grading.judge import behaviours, metrics
from exp_assignment2.grading.judge.trace import NotJudged
from exp_assignment2.grading.plan.profile_keys import with_shared

SWEEP = 0.3          # rad: a head turned this far at a stop is looking around


def percentile(values, share):
    values = sorted(values)
    if not values:
        return None
    return values[min(len(values) - 1, int(round(share * (len(values) - 1))))]


def distances(trace, roles, check):
    """{'stop_distances': [m from the ball where the head turned widest at each stop
    it looked around at], 'sweeps': [rad the head turned each way there, the lesser],
    'trailing': [m to the moving ball while it was in view, the robot awake]}."""
    track = bt.samples(trace, roles.robot.name, roles.ball.name, roles.head.name,
                       check.get('arena'))
    speeds, sight = bt.ball_speeds(track), bt.Sight(trace, roles, check)
    asleep = behaviours._asleep(track, check)
    grace = float(check.get('grace', behaviours.GRACE))
    out = {'stop_distances': [], 'sweeps': [], 'trailing': []}
    for a, b in bt.stops(track, speeds, float(check.get('stop', 3.0))):
        during = [(k, s) for k, s in enumerate(track[a:], a)
                  if s.t <= track[b].t + grace and s.head is not None]
        if not during:
            continue
        widest = max(during, key=lambda p: abs(p[1].head))
        sweep = min(max(s.head for _, s in during), -min(s.head for _, s in during))
        if sweep >= SWEEP:
            out['stop_distances'].append(round(bt.distance(widest[1]), 3))
            out['sweeps'].append(round(sweep, 3))
    for i, s in enumerate(track):
        if speeds[i] is not None and speeds[i] >= bt.MOVING and i not in asleep \
                and sight.sees(s):
            out['trailing'].append(round(bt.distance(s), 3))
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



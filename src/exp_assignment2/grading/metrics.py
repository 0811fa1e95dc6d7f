"""Figures of a run from what was observed outside the student's code (no ROS):
the simulator's ground truth (:class:`Trace`) and the tracebacks found in the
run's logs (read by :mod:`exp_assignment2.grading.logs`).

Each metric is ``fn(trace, profile, check) -> (value, detail)``; a profile's
check names one in ``metric`` and gives its thresholds (``min``/``max``) and
its own settings (``reach``, ``joint``, ...). ``value`` None means the
figure could not be had (the check then fails, saying why in ``detail``).
"""
import math

RESET_JUMP = 3.0     # m in one sample (0.1 s): a reset or a teleport, not a path


class Trace(object):
    """The ground truth of one run: ``states`` (time-ordered dicts with
    ``t``, ``models``, ``joints``), ``topics`` (list of (t, topic, msg))
    and ``errors`` (the Python tracebacks found in the logs)."""

    def __init__(self, states=(), topics=(), errors=()):
        self.states = sorted(states, key=lambda s: s['t'])
        self.topics = list(topics)
        self.errors = list(errors)

    @property
    def duration(self):
        return self.states[-1]['t'] if self.states else 0.0

    def xy(self, model):
        """[(t, x, y)] of a model while it existed."""
        out = []
        for state in self.states:
            pose = state['models'].get(model)
            if pose and pose[0] is not None and pose[1] is not None:
                out.append((state['t'], pose[0], pose[1]))
        return out

    def joint(self, model, fragment):
        """(joint name, [(t, position)]) of the model's first joint whose name holds
        ``fragment``; (None, []) if it has none."""
        for state in self.states:
            for name in sorted(state['joints'].get(model) or {}):
                if fragment in name:
                    return name, [(s['t'], (s['joints'].get(model) or {}).get(name))
                                  for s in self.states
                                  if (s['joints'].get(model) or {}).get(name) is not None]
        return None, []

    def distances(self, a, b):
        """[(t, planar distance)] between two models, where both were seen."""
        out = []
        for state in self.states:
            pa, pb = state['models'].get(a), state['models'].get(b)
            if pa and pb and None not in pa[:2] and None not in pb[:2]:
                out.append((state['t'], math.hypot(pa[0] - pb[0], pa[1] - pb[1])))
        return out


def _visits(distances, reach):
    """[(t_in, t_out)] of the stays within ``reach`` (out again past 1.25 reach)."""
    visits, start = [], None
    for t, d in distances:
        if start is None and d <= reach:
            start = t
        elif start is not None and d > 1.25 * reach:
            visits.append((start, t))
            start = None
    if start is not None:
        visits.append((start, distances[-1][0]))
    return visits


def approaches(trace, profile, check):
    if not profile.get('ball'):
        return None, 'the profile names no ball'
    distances = trace.distances(profile['robot'], profile['ball'])
    if not distances:
        return None, 'no pose of %s and %s in the ground truth' % (profile['robot'],
                                                                   profile['ball'])
    visits = _visits(distances, check.get('reach', 2.0))
    closest = min(d for _, d in distances)
    return len(visits), 'closest %.2f m' % closest


def first_approach_time(trace, profile, check):
    distances = trace.distances(profile['robot'], profile.get('ball') or '')
    visits = _visits(distances, check.get('reach', 2.0))
    if not visits:
        return None, 'never within %.1f m' % check.get('reach', 2.0)
    return round(visits[0][0], 1), 'at t = %.1f s' % visits[0][0]


def head_turn_near_ball(trace, profile, check):
    """The widest range of the head's angle during one stay near the ball."""
    name, angles = trace.joint(profile['robot'], check.get('joint', 'head'))
    if name is None:
        return None, 'the robot has no joint named like %r' % check.get('joint', 'head')
    distances = trace.distances(profile['robot'], profile.get('ball') or '')
    best = 0.0
    for t_in, t_out in _visits(distances, check.get('reach', 2.5)):
        during = [a for t, a in angles if t_in <= t <= t_out]
        if during:
            best = max(best, max(during) - min(during))
    return round(best, 3), '%s, %.0f deg' % (name, math.degrees(best))


def path_length(trace, profile, check):
    points = trace.xy(profile['robot'])
    if not points:
        return None, 'no pose of %s in the ground truth' % profile['robot']
    total = 0.0
    for (_, x0, y0), (_, x1, y1) in zip(points, points[1:]):
        step = math.hypot(x1 - x0, y1 - y0)
        if step < RESET_JUMP:
            total += step
    return round(total, 2), '%.1f m in %.0f s' % (total, points[-1][0] - points[0][0])


def python_errors(trace, profile, check):
    first = trace.errors[0]['summary'] if trace.errors else ''
    return len(trace.errors), first


def _targets(trace, topic):
    """[(t, (x, y))] commanded on ``topic`` (an array message's first two numbers,
    or a point's/pose's x, y)."""
    out = []
    for t, name, msg in trace.topics:
        if name != topic or not isinstance(msg, dict):
            continue
        point = msg
        for key in ('pose', 'position'):          # a PoseStamped's, a Pose's, a Point's x, y
            if isinstance(point.get(key), dict):
                point = point[key]
        if isinstance(msg.get('data'), list) and len(msg['data']) >= 2:
            out.append((t, (float(msg['data'][0]), float(msg['data'][1]))))
        elif 'x' in point and 'y' in point:
            out.append((t, (float(point['x']), float(point['y']))))
    return out


def _arrivals(trace, profile, check):
    targets = _targets(trace, check.get('topic', '/target_pos'))
    points = trace.xy(profile['robot'])
    tolerance = check.get('tolerance', 0.5)
    reached = 0
    for i, (t, (x, y)) in enumerate(targets):
        until = targets[i + 1][0] if i + 1 < len(targets) else float('inf')
        if any(t <= tp <= until and math.hypot(px - x, py - y) <= tolerance
               for tp, px, py in points):
            reached += 1
    return reached, len(targets)


def arrivals(trace, profile, check):
    reached, commanded = _arrivals(trace, profile, check)
    return reached, '%d of %d targets' % (reached, commanded)


def arrival_ratio(trace, profile, check):
    reached, commanded = _arrivals(trace, profile, check)
    if not commanded:
        return None, 'no target was commanded on %s' % check.get('topic', '/target_pos')
    return round(reached / commanded, 3), '%d of %d targets' % (reached, commanded)


METRICS = {fn.__name__: fn for fn in (approaches, first_approach_time, head_turn_near_ball,
                                      path_length, python_errors, arrivals, arrival_ratio)}


def evaluate(trace, profile):
    """[{name, metric, value, threshold, passed, detail}] for the profile's checks."""
    results = []
    for check in profile['checks']:
        value, detail = METRICS[check['metric']](trace, profile, check)
        low, high = check.get('min'), check.get('max')
        passed = value is not None and (low is None or value >= low) and \
            (high is None or value <= high)
        threshold = ('>= %g' % low if low is not None else '') + \
            (' and ' if low is not None and high is not None else '') + \
            ('<= %g' % high if high is not None else '')
        results.append({'name': check['name'], 'metric': check['metric'], 'value': value,
                        'threshold': threshold, 'passed': bool(passed), 'detail': detail})
    return results


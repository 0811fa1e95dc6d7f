"""Figures of a run from what was observed outside the student's code (no ROS):
the simulator's ground truth (:class:`Trace`) and the tracebacks found in the
run's logs (read by :mod:`exp_assignment2.grading.judge.logs`).

Each metric is ``fn(trace, roles, check) -> (value, detail)``: ``roles`` are
the run's robot, head and ball, found by their roles whatever the student
named them (:mod:`exp_assignment2.grading.judge.roles`); a profile's check names a
metric in ``metric`` and gives its thresholds (``min``/``max``) and its own
settings (``reach``, ``topic``, ...). ``value`` None means the figure could
not be had (the check then fails, saying why in ``detail``). A check whose
robot, head or ball cannot be told is not run at all (:class:`NotJudged`):
its result says why, and it is neither passed nor failed.
"""
import math

from exp_assignment2.grading.judge import roles as roles_
from exp_assignment2.grading.run.truth import read_record

RESET_JUMP = 3.0     # m in one sample (0.1 s): a reset or a teleport, not a path


class NotJudged(Exception):
    """The check cannot be run: a role it needs cannot be told (the reason)."""


class Absent(Exception):
    """What the check needs is not in the world (the reason): the check fails."""


def need(role):
    """A role's name, or :class:`Absent` / :class:`NotJudged` saying why there is none."""
    if role.name is None:
        raise (Absent if role.absent else NotJudged)(role.why)
    return role.name


class Trace(object):
    """The ground truth of one run: ``states`` (time-ordered dicts with ``t``,
    ``models``, ``joints`` and the counters ``fed`` and ``placed``), ``topics``
    (list of (t, topic, msg)), ``errors`` (the Python tracebacks found in the
    logs) and ``models`` (what the simulator said of each model: name -> facts)."""

    def __init__(self, states=(), topics=(), errors=(), models=None):
        self.states = sorted(states, key=lambda s: s['t'])
        self.topics = list(topics)
        self.errors = list(errors)
        self.models = dict(models or {})

    @classmethod
    def from_record(cls, record_dir, errors=()):
        """The run's trace, from its record
        (:func:`~exp_assignment2.grading.run.truth.read_record`)."""
        found = read_record(record_dir)
        return cls(found.states, found.topics, errors, found.models)

    @property
    def duration(self):
        return self.states[-1]['t'] if self.states else 0.0

    def seen(self, model):
        """The model was in the world at some time of the record."""
        return model in self.models or any(model in s['models'] for s in self.states)

    def counter(self, kind, model):
        """The last count of ``fed`` (commands its drive took) or ``placed``."""
        return max([int((s.get(kind) or {}).get(model) or 0) for s in self.states] or [0])

    def travelled(self, model):
        """m the model went in the plane (resets and teleports left out)."""
        points = self.xy(model)
        return sum(step for step in (math.hypot(x1 - x0, y1 - y0) for (_, x0, y0), (_, x1, y1)
                                     in zip(points, points[1:])) if step < RESET_JUMP)

    def joint_names(self, model):
        """Every moving joint of the model in the record, by name."""
        names = set()
        for state in self.states:
            names.update((state['joints'].get(model) or {}))
        return sorted(names)

    def topic(self, name, namespace=''):
        """[(t, msg)] of a recorded topic; a relative name is the robot's (``namespace``)."""
        if not name.startswith('/'):
            name = '/%s/%s' % (namespace, name) if namespace else '/' + name
        return [(t, msg) for t, topic, msg in self.topics if topic == name]

    def xy(self, model):
        """[(t, x, y)] of a model while it existed."""
        out = []
        for state in self.states:
            pose = state['models'].get(model)
            if pose and pose[0] is not None and pose[1] is not None:
                out.append((state['t'], pose[0], pose[1]))
        return out

    def angles(self, model, joint):
        """[(t, position)] of one joint of the model."""
        return [(s['t'], (s['joints'].get(model) or {}).get(joint)) for s in self.states
                if (s['joints'].get(model) or {}).get(joint) is not None]

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


def approaches(trace, roles, check):
    robot, ball = need(roles.robot), need(roles.ball)
    distances = trace.distances(robot, ball)
    if not distances:
        return None, 'no pose of %s and %s in the ground truth' % (robot, ball)
    visits = _visits(distances, check.get('reach', 2.0))
    closest = min(d for _, d in distances)
    return len(visits), 'closest %.2f m' % closest


def first_approach_time(trace, roles, check):
    distances = trace.distances(need(roles.robot), need(roles.ball))
    visits = _visits(distances, check.get('reach', 2.0))
    if not visits:
        return None, 'never within %.1f m' % check.get('reach', 2.0)
    return round(visits[0][0], 1), 'at t = %.1f s' % visits[0][0]


def head_turn_near_ball(trace, roles, check):
    """The widest range of the head's angle during one stay near the ball."""
    robot, ball = need(roles.robot), need(roles.ball)
    joint = need(roles.head)
    angles = trace.angles(robot, joint)
    best = 0.0
    for t_in, t_out in _visits(trace.distances(robot, ball), check.get('reach', 2.5)):
        during = [a for t, a in angles if t_in <= t <= t_out]
        if during:
            best = max(best, max(during) - min(during))
    return round(best, 3), '%s, %.0f deg' % (joint, math.degrees(best))


def path_length(trace, roles, check):
    robot = need(roles.robot)
    points = trace.xy(robot)
    if not points:
        return None, 'no pose of %s in the ground truth' % robot
    total = trace.travelled(robot)
    return round(total, 2), '%.1f m in %.0f s' % (total, points[-1][0] - points[0][0])


def python_errors(trace, roles, check):
    first = trace.errors[0]['summary'] if trace.errors else ''
    return len(trace.errors), first


def _targets(trace, topic, namespace):
    """[(t, (x, y))] commanded on ``topic`` (an array message's first two numbers,
    or a point's/pose's x, y; a relative name is under the robot's namespace)."""
    out = []
    for t, msg in trace.topic(topic, namespace):
        if not isinstance(msg, dict):
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


def _arrivals(trace, roles, check):
    targets = _targets(trace, check.get('topic', '/target_pos'), roles.namespace)
    points = trace.xy(need(roles.robot))
    tolerance = check.get('tolerance', 0.5)
    reached = 0
    for i, (t, (x, y)) in enumerate(targets):
        until = targets[i + 1][0] if i + 1 < len(targets) else float('inf')
        if any(t <= tp <= until and math.hypot(px - x, py - y) <= tolerance
               for tp, px, py in points):
            reached += 1
    return reached, len(targets)


def arrivals(trace, roles, check):
    reached, commanded = _arrivals(trace, roles, check)
    return reached, '%d of %d targets' % (reached, commanded)


def arrival_ratio(trace, roles, check):
    reached, commanded = _arrivals(trace, roles, check)
    if not commanded:
        return None, 'no target was commanded on %s' % check.get('topic', '/target_pos')
    return round(reached / commanded, 3), '%d of %d targets' % (reached, commanded)


METRICS = {fn.__name__: fn for fn in (approaches, first_approach_time, head_turn_near_ball,
                                      path_length, python_errors, arrivals, arrival_ratio)}
# the roles each metric judges (the camera: its pictures, beside the head)
NEEDS = {'approaches': ('robot', 'ball'), 'first_approach_time': ('robot', 'ball'),
         'head_turn_near_ball': ('robot', 'head', 'camera', 'ball'), 'path_length': ('robot',),
         'python_errors': (), 'arrivals': ('robot',), 'arrival_ratio': ('robot',)}


def roles_needed(checks):
    """The roles (robot, head, camera, ball) the checks judge."""
    return {role for check in checks for role in NEEDS.get(check.get('metric'), ())}


def threshold_text(check):
    low, high = check.get('min'), check.get('max')
    return ('>= %g' % low if low is not None else '') + \
        (' and ' if low is not None and high is not None else '') + \
        ('<= %g' % high if high is not None else '')


def evaluate(trace, profile, roles=None):
    """[{name, metric, value, threshold, passed, judged, detail}] for the profile's
    checks, judging ``roles`` (default: found in the trace,
    :func:`~exp_assignment2.grading.judge.roles.find`).
    A check not run (``judged`` False) has ``passed`` None and says why in ``detail``."""
    roles = roles if roles is not None else roles_.find(trace, profile)
    results = []
    for check in profile['checks']:
        judged = True
        try:
            value, detail = METRICS[check['metric']](trace, roles, check)
        except Absent as why:
            value, detail = None, str(why)
        except NotJudged as why:
            value, detail, judged = None, 'not judged: %s' % why, False
        low, high = check.get('min'), check.get('max')
        passed = value is not None and (low is None or value >= low) and \
            (high is None or value <= high)
        results.append({'name': check['name'], 'metric': check['metric'], 'value': value,
                        'threshold': threshold_text(check),
                        'passed': bool(passed) if judged else None, 'judged': judged,
                        'detail': detail})
    return results

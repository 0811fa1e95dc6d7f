"""Hand-made ground truth for the tests of the behaviours' checks
(test_grading_behaviours.py, test_grading_head_arrivals.py; no ROS): a robot's
and a ball's paths at 10 Hz, the head's angle, and the dog profile's checks."""
from exp_assignment2.grading.judge import metrics
from exp_assignment2.grading.judge.roles import Role, Roles
from exp_assignment2.grading.plan import profiles

DOG = profiles.load('dog')
ROLES = Roles(robot=Role('robot', ''), head=Role('joint_head', ''),
              camera=Role('robot/camera1', ''), ball=Role('ball', ''))
HIDDEN = -3.0


def trace(robot, ball, until=60.0, head=lambda t: 0.0, models=None):
    """10 Hz states: ``robot(t)`` -> (x, y, yaw), ``ball(t)`` -> (x, y, z)."""
    states = []
    for i in range(int(until * 10) + 1):
        t = i / 10.0
        x, y, yaw = robot(t)
        states.append({'t': t, 'models': {'robot': [x, y, 0.1, yaw], 'ball': list(ball(t)) + [0]},
                       'joints': {'robot': {'joint_head': head(t)}}})
    return metrics.Trace(states, models=models)


def check(metric, **settings):
    """The dog profile's check of ``metric``, with ``settings`` over it."""
    spec = next(c for c in DOG['checks'] if c['metric'] == metric)
    return metrics.with_shared(dict(spec, **settings), DOG)


def figure(trace_, metric, **settings):
    got = metrics.METRICS[metric](trace_, ROLES, check(metric, **settings))
    return got[0], got[1], (got[2] if len(got) > 2 else None)


def still(x=0.0, y=0.0, yaw=0.0):
    return lambda t: (x, y, yaw)


def line(x0, x1, t0, t1, y=0.0):
    """From (x0, y) to (x1, y) between t0 and t1 s, facing +x."""
    return lambda t: (x0 + (x1 - x0) * min(1.0, max(0.0, (t - t0) / (t1 - t0))), y, 0.0)


def arrives(x, at, x0=-6.0):
    """Drives from (x0, 0) facing +x, at 1 m/s, and rests at (x, 0) from ``at`` s."""
    return line(x0, x, at - (x - x0), at)


def sweep(t0, turn, left=0.5, right=-0.5):
    """The head to ``left`` for ``turn`` s from ``t0``, then to ``right`` for ``turn`` s,
    then back to 0."""
    return lambda t: left if t0 <= t < t0 + turn else right if t0 + turn <= t < t0 + 2 * turn \
        else 0.0

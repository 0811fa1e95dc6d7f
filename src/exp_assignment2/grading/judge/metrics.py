"""Figures of a run from what was observed outside the student's code (no ROS):
the simulator's ground truth (:class:`Trace`) and the tracebacks found in the
run's logs (read by :mod:`exp_assignment2.grading.judge.logs`).

Each metric is ``fn(trace, roles, check) -> (value, detail[, at])``: ``roles``
are the run's robot, head and ball, found by their roles whatever the student
named them (:mod:`exp_assignment2.grading.judge.roles`); a profile's check names
a metric in ``metric`` and gives its thresholds (``min``/``max``) and its own
settings (``reach``, ``topic``, ...; those the profile shares, such as
``reach``, where it gives none); ``at`` is the simulated s the figure was
decided at (the page shows the camera then); a fourth, ``limits``, a threshold
the run's occasion scales (``{'min': 3}``: three places for the minute the ball was
out of sight), used for this run in place of the profile's. ``value`` None means the figure
could not be had (the check then fails, saying why in ``detail``). A check
whose robot, head or ball cannot be told, or whose behaviour the run gave no
occasion for, is not run at all (:class:`NotJudged`): its result says why,
and it is neither passed nor failed. The assignment's behaviours are in
:mod:`~exp_assignment2.grading.judge.behaviours`.
"""
import math

from exp_assignment2.grading.judge import ball_track, behaviours, reach as reach_
from exp_assignment2.grading.judge import roles as roles_
from exp_assignment2.grading.judge.trace import (  # noqa: F401 -- this module's words too
    RESET_JUMP, Absent, NotJudged, Trace, need)
from exp_assignment2.grading.plan.profile_keys import with_shared


def _stays(trace, roles, check):
    """(the track, the stays near the ball) of a check (:mod:`.reach`)."""
    robot, ball = need(roles.robot), need(roles.ball)
    track = ball_track.samples(trace, robot, ball, arena=check.get('arena'))
    reach, own, closing = reach_.settings(check)
    return track, reach_.stays(track, reach, own, closing)


def _said(track, found, check):
    """A detail's words on the stays that were not the robot's reaches."""
    reach = reach_.settings(check)[0]
    theirs = sum(1 for s in found if not s.robots)
    hidden = reach_.over_hidden(track, reach)
    return ''.join([', %d the ball\'s coming, not the robot\'s reach' % theirs if theirs else '',
                    ', %d over the ball while it was gone (not counted)' % hidden
                    if hidden else ''])


def _first_there(track, found, roles, check):
    """The first sample the ball was there (on the ground, in the arena), or
    :class:`NotJudged`: the run gave the robot no ball to reach (none there; or one
    never out of reach, the robot spawned beside a ball that stayed, and it did not
    drive at it: there was nothing to reach)."""
    first = next((s for s in track if s.there), None)
    if first is None:
        raise NotJudged('%s was never on the ground in the arena beside %s: no ball to reach'
                        % (roles.ball.name, roles.robot.name))
    reach = reach_.settings(check)[0]
    if not any(s.robots for s in found) and \
            not any(s.there and ball_track.distance(s) > reach for s in track):
        raise NotJudged('%s was never farther than %g m from %s while on the ground: nothing '
                        'to reach (it started beside a ball that stayed)' % (
                            roles.ball.name, reach, roles.robot.name))
    return first


def approaches(trace, roles, check):
    """Times the robot reached a ball that was there, by its own motion (:mod:`.reach`)."""
    track, found = _stays(trace, roles, check)
    _first_there(track, found, roles, check)
    near = [ball_track.distance(s) for s in track if s.there]
    mine = [s for s in found if s.robots]
    return len(mine), 'closest %.2f m; within %.2f m %d times%s' % (
        min(near), reach_.settings(check)[0], len(mine), _said(track, found, check)), \
        mine[0].at if mine else min(track, key=lambda s: ball_track.distance(s) if s.there
                                    else float('inf')).t


def first_approach_time(trace, roles, check):
    """s from the ball's first time on the ground in the arena (the robot's first
    occasion to reach it) to the robot's first reach."""
    track, found = _stays(trace, roles, check)
    first = _first_there(track, found, roles, check)
    start = first.t if first.t > track[0].t + 1.0 else 0.0     # there from the start: t = 0
    mine = [s for s in found if s.robots]
    if not mine:
        limit = check.get('max')
        if limit is not None and track[-1].t - start < float(limit):
            raise NotJudged('the ball was first on the ground at t = %.1f s, %.0f s before the '
                            'run\'s end: less than the %g s a first reach is given' % (
                                start, track[-1].t - start, float(limit)))
        return None, 'never reached it within %.2f m%s' % (reach_.settings(check)[0],
                                                             _said(track, found, check))
    took = mine[0].at - start
    detail = 'at t = %.1f s' % mine[0].at
    if start:
        detail += ', %.1f s after the ball was first on the ground (t = %.1f s)' % (took, start)
    return round(took, 1), detail, mine[0].at


def head_turn_near_ball(trace, roles, check):
    """The widest range of the head's angle during one stay near the ball (the
    same stays as the reach's, with the same ``reach``)."""
    joint = need(roles.head)
    track, found = _stays(trace, roles, check)
    angles = trace.angles(roles.robot.name, joint)
    best, at = 0.0, None
    for stay in found:
        during = [(a, t) for t, a in angles if stay.t_in <= t <= stay.t_out]
        if during and max(during)[0] - min(during)[0] > best:
            best = max(during)[0] - min(during)[0]
            at = max(max(during)[1], min(during)[1])
    return round(best, 3), '%s, %.0f deg' % (joint, math.degrees(best)), at


def path_length(trace, roles, check):
    """m the robot drove: positions over a second, steps under 5 cm left out
    (:meth:`Trace.driven`)."""
    robot = need(roles.robot)
    points = trace.xy(robot)
    if not points:
        return None, 'no pose of %s in the ground truth' % robot
    total = trace.driven(robot)
    return round(total, 2), '%.1f m in %.0f s (positions over a second, steps under 5 cm ' \
        'left out: jitter in place is not driving)' % (total, points[-1][0] - points[0][0])


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
METRICS.update(behaviours.METRICS)
# the roles each metric judges (the camera: its pictures, beside the head)
NEEDS = {'approaches': ('robot', 'ball'), 'first_approach_time': ('robot', 'ball'),
         'head_turn_near_ball': ('robot', 'head', 'camera', 'ball'), 'path_length': ('robot',),
         'python_errors': (), 'arrivals': ('robot',), 'arrival_ratio': ('robot',)}
NEEDS.update(behaviours.NEEDS)


def roles_needed(checks):
    """The roles (robot, head, camera, ball) the checks judge."""
    return {role for check in checks for role in NEEDS.get(check.get('metric'), ())}


def threshold_text(check):
    low, high = check.get('min'), check.get('max')
    return ('>= %g' % low if low is not None else '') + \
        (' and ' if low is not None and high is not None else '') + \
        ('<= %g' % high if high is not None else '')


def evaluate(trace, profile, roles=None):
    """[{name, metric, value, threshold, passed, judged, detail, at}] for the profile's
    checks, judging ``roles`` (default: found in the trace,
    :func:`~exp_assignment2.grading.judge.roles.find`). A check not run (``judged``
    False) has ``passed`` None and says why in ``detail``; ``at``: the simulated s
    the figure was decided at (None: the whole run's)."""
    roles = roles if roles is not None else roles_.find(trace, profile)
    results = []
    for check in profile['checks']:
        judged, at, limits = True, None, {}
        try:
            got = METRICS[check['metric']](trace, roles, with_shared(check, profile))
            value, detail = got[:2]
            at = round(got[2], 1) if len(got) > 2 and got[2] is not None else None
            limits = got[3] if len(got) > 3 else {}
        except Absent as why:
            value, detail = None, str(why)
        except NotJudged as why:
            value, detail, judged = None, 'not judged: %s' % why, False
        low, high = limits.get('min', check.get('min')), limits.get('max', check.get('max'))
        passed = value is not None and (low is None or value >= low) and \
            (high is None or value <= high)
        results.append(dict({'name': check['name'], 'metric': check['metric'], 'value': value,
                             'threshold': threshold_text(dict(check, **limits)),
                             'passed': bool(passed) if judged else None, 'judged': judged,
                             'detail': detail, 'at': at}, **({'limits': limits} if limits
                                                             else {})))
    return results

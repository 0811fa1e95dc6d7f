"""The assignment's three behaviours, judged from what the robot did (no ROS;
docs/grading.md, "What works means"): NORMAL (it wanders), SLEEP (it goes home
and rests), PLAY (it follows the moving ball, turns its head both ways when
it has come to rest at the ball, gives the ball up when it is gone).

Each metric is as :mod:`~exp_assignment2.grading.judge.metrics` has them,
returning the simulated s its figure was decided at. A behaviour the run gave
no occasion for (the ball never hidden, never moving, a run too short for a
sleep that comes at random) raises :class:`NotJudged`, as a role that cannot
be told does: not judged, its points left for the teacher, never failed.
"""
import collections
import math

from exp_assignment2.grading.judge import arrivals
from exp_assignment2.grading.judge import ball_track as bt
from exp_assignment2.grading.judge.reach import OUT
from exp_assignment2.grading.judge.trace import NotJudged, need

ARRIVE = 1.0        # m beyond its radius the robot was before a rest: it came there
REST = 10.0         # s: a rest this long away from the ball is a sleep (follows, looks)
STILL = 0.3         # m: a robot resting at a place of its own stays this close to it
STILL_YAW = 0.35    # rad: and turns no more than this
STILL_TURN = 0.25   # rad: nor turns more than this within any second (a turn is no rest)
SLACK = 1.0         # s: a run of its full duration may end a state short of it


def _track(trace, roles, check, ball=True, head=False):
    robot = need(roles.robot)
    name = need(roles.ball) if ball else roles.ball.name
    joint = need(roles.head) if head else roles.head.name
    track = bt.samples(trace, robot, name, joint, check.get('arena'))
    if not track:
        raise NotJudged('no pose of %s in the ground truth' % robot)
    return track


def _reach(check):
    return float(check.get('reach', 2.0))


def rests(track, check, least):
    """[(i0, i1, x, y)]: the robot came (from more than its radius + ARRIVE m
    away) to its home, the profile's ``home``, and stayed within ``radius`` m of
    it ``least`` s; without a home, to any place away from the ball (a home of
    its own), where it stayed still (within :data:`STILL` m, its heading within
    :data:`STILL_YAW` rad and turning no more than :data:`STILL_TURN` rad within a
    second: a dog turning on the spot to search, or to set off, is not asleep)."""
    home = check.get('home')
    radius = float(check.get('radius', check.get('home_radius', 1.0)))
    radius = radius if home else min(radius, STILL)
    far = OUT * _reach(check)
    pts = bt.smoothed([(s.t, s.rx, s.ry) for s in track])
    gap = lambda i, x, y: math.hypot(pts[i][1] - x, pts[i][2] - y)  # noqa: E731
    turned = lambda i, j: home is None and (  # noqa: E731
        _turn(track[i].ryaw, track[j].ryaw) > STILL_YAW or _turning(track, j) > STILL_TURN)
    found, i = [], 0
    while i < len(pts):
        x, y = home if home else pts[i][1:]
        j = i
        while j + 1 < len(pts) and gap(j + 1, x, y) <= radius and not turned(i, j + 1):
            j += 1
        if gap(i, x, y) <= radius and pts[j][0] - pts[i][0] >= least:
            if (home or not (track[i].there and bt.distance(track[i]) <= far)) and \
                    any(gap(k, x, y) > radius + ARRIVE for k in range(i)):
                found.append((i, j, x, y))
            i = j + 1       # a stay it did not come to (spawned there), or at the ball: whole
        else:
            i += 1
    return found


def _turning(track, j, second=1.0):
    """rad: the widest turn between the robot's headings in the second up to sample j
    (0 where unknown): a turn on the spot, not the jolt of one sample."""
    k = j
    while k > 0 and track[k - 1].t > track[j].t - second:
        k -= 1
    return max([_turn(track[a].ryaw, track[b].ryaw) for a in range(k, j + 1)
                for b in range(a + 1, j + 1)] or [0.0])


def _turn(a, b):
    """rad between two headings (0 where one is unknown)."""
    if a is None or b is None:
        return 0.0
    return abs(math.atan2(math.sin(a - b), math.cos(a - b)))


def _asleep(track, check):
    """Indices of samples in the robot's sleeps (rests of ``rest`` s): the ball is ignored then."""
    return {k for a, b, _, _ in rests(track, check, float(check.get('rest', REST)))
            for k in range(a, b + 1)}


def sleeps(trace, roles, check):
    """The longest rest at home (s)."""
    track = _track(trace, roles, check, ball=False)
    least = float(check.get('min', REST))
    found = rests(track, check, least / 2.0)
    home = check.get('home')
    where = 'home (%g, %g)' % tuple(home) if home else 'a place of its own, away from the ball'
    if not found:
        if trace.duration < float(check.get('occasion', 0.0)) - SLACK:
            raise NotJudged('no rest at %s in %.0f s, and a sleep may come later (it comes at '
                            'random: %g s is a run long enough for it)' % (
                                where, trace.duration, check['occasion']))
        unseen = _unseen(trace, roles, check)
        if unseen is not None and unseen < float(check.get('unseen', 0.0)):
            raise NotJudged('no rest at %s; the ball was out of the robot\'s sight %.0f s at '
                            'the longest (it plays while it sees the ball: %g s at a time out of '
                            'its sight give it the occasion to sleep)' % (
                                where, unseen, check['unseen']))
        radius = float(check.get('radius', check.get('home_radius', 1.0)))
        return 0.0, 'never came to %s and stayed within %.1f m of it %g s' % (
            where, radius if home else min(radius, STILL), least / 2.0), None
    a, b, x, y = max(found, key=lambda r: track[r[1]].t - track[r[0]].t)
    rested = track[b].t - track[a].t
    if rested < least and trace.duration < float(check.get('occasion', 0.0)) - SLACK:
        raise NotJudged('rested only %.1f s in a run of %.0f s (a sleep comes at random: a run '
                        'of %g s gives it its occasion)' % (rested, trace.duration,
                                                             check['occasion']))
    return round(rested, 1), 'rested %.1f s at %s (%.1f, %.1f) from t = %.1f s' % (
        rested, 'home' if home else 'its own home', x, y, track[a].t), \
        track[a].t + min(rested, least)


def _unseen(trace, roles, check):
    """The longest time (s) the ball was out of the robot's sight at a stretch (gone, or
    out of its camera's view), or None when the ball or the camera cannot be told."""
    if roles.ball.name is None or roles.robot.name is None:
        return None
    track = bt.samples(trace, roles.robot.name, roles.ball.name, roles.head.name,
                       check.get('arena'))
    sight = bt.Sight(trace, roles, check)
    return max([track[b].t - track[a].t for a, b in bt.spans(
        track, lambda i: not sight.sees(track[i]))] or [0.0])


def wandered(trace, roles, check):
    """([s it reached each new place], s the ball was out of its sight in spells of
    ``gap`` s or more, the first such spell's start or None): places ``spacing`` m
    apart it drove to while the ball was out of its sight."""
    track = _track(trace, roles, check)
    sight, reach = bt.Sight(trace, roles, check), _reach(check)
    spacing, least = float(check.get('spacing', 2.0)), float(check.get('gap', 5.0))
    seen = [sight.sees(s) or (s.there and bt.distance(s) <= reach) for s in track]
    out = [(a, b) for a, b in bt.spans(track, lambda i: not seen[i])
           if track[b].t - track[a].t >= least]
    pts = bt.smoothed([(s.t, s.rx, s.ry) for s in track])
    places, times = [pts[0][1:]], []
    for a, b in out:
        for t, x, y in pts[a:b + 1]:
            if all(math.hypot(x - p[0], y - p[1]) >= spacing for p in places):
                places.append((x, y))
                times.append(t)
    return times, sum(track[b].t - track[a].t for a, b in out), \
        track[out[0][0]].t if out else None


def wanders(trace, roles, check):
    """Distinct places (``spacing`` m apart) it drove to while the ball was out of its sight."""
    times, total, first = wandered(trace, roles, check)
    spacing, least = float(check.get('spacing', 2.0)), float(check.get('gap', 5.0))
    want = int(check.get('min', 1))
    if total < float(check.get('occasion', 0.0)) and len(times) < want:
        raise NotJudged('the ball was out of the robot\'s sight %.0f s in all (spells of %g s '
                        'or more), less than the %g s that give it the occasion to wander'
                        % (total, least, check['occasion']))
    # the places a run's time out of sight asks for: one each ``per`` s, up to ``min``
    per, limits = check.get('per'), {}
    if per and total < want * float(per):
        want = max(1, int(total // float(per)))
        limits = {'min': want}
    return len(times), '%d places %g m apart driven to while the ball was out of its sight ' \
        '(%.0f s in all%s)' % (len(times), spacing, total, ', time for %d at one each %g s' % (
            want, float(per)) if limits else ''), \
        (times[want - 1] if len(times) >= want else times[-1] if times else first), limits


def follows_ball(trace, roles, check):
    """Share of the time the ball moved (outside the robot's sleeps) it kept within ``follow`` m."""
    track = _track(trace, roles, check)
    speeds, asleep = bt.ball_speeds(track), _asleep(track, check)
    follow, moving = float(check.get('follow', 5.0)), float(check.get('moving', bt.MOVING))
    total = near = 0.0
    run, best, at = 0.0, 0.0, None
    for i in range(len(track) - 1):
        if speeds[i] is None or speeds[i] < moving or i in asleep:
            run = 0.0
            continue
        dt = min(track[i + 1].t - track[i].t, 0.5)
        total += dt
        if bt.distance(track[i]) <= follow:
            near, run = near + dt, run + dt
            if run > best:
                best, at = run, track[i].t - run / 2.0
        else:
            run = 0.0
    if total < float(check.get('occasion', 0.0)) or total == 0.0:
        raise NotJudged('the ball moved %.0f s (outside the robot\'s sleeps), less than the '
                        '%g s that give it the occasion to follow' % (
                            total, float(check.get('occasion', 0.0))))
    return round(near / total, 3), 'within %g m of the moving ball %.0f of %.0f s' % (
        follow, near, total), at


def looks_both_ways(trace, roles, check):
    """Share of the robot's arrivals at the ball (it came to rest within ``reach`` of
    a ball in front of its camera it was approaching, awake) after which it turned its
    head at least ``angle`` rad to each side within ``window`` s, whatever the ball did
    meanwhile (:mod:`~exp_assignment2.grading.judge.arrivals`)."""
    track = _track(trace, roles, check, head=True)
    reach, angle = _reach(check), float(check.get('angle', 0.3))
    window = float(check.get('window', arrivals.WINDOW))
    found = arrivals.arrivals(track, reach, bt.Sight(trace, roles, check),
                              _asleep(track, check))
    seen = arrivals.looks(track, found, angle, window)
    counted = [look for look in seen if not look.cut or look.left and look.right]
    if not counted and seen:
        raise NotJudged('the robot came to rest at the ball %d times, each with less than %g s '
                        'of the run left to look around' % (len(seen), window))
    if not counted:
        why = collections.Counter(w for _, w, _ in found if w)
        raise NotJudged('the robot never came to rest within %g m of the ball in front of it '
                        '(%d rests%s)' % (reach, len(found), ''.join(
                            '; %d: %s' % (n, w) for w, n in why.most_common(3))))
    swept = [look for look in counted if look.left is not None and look.right is not None]
    return round(len(swept) / float(len(counted)), 3), '%s: after %d of the %d times it ' \
        'came to rest within %g m of the ball (in view), turned the head at least %g rad each ' \
        'way within %g s' % (roles.head.name, len(swept), len(counted), reach, angle, window), \
        swept[0].done if swept else counted[0].t


def gives_up_ball(trace, roles, check):
    """The longest time (s) the robot took to leave (``leave`` m) after the ball
    near it was gone."""
    track = _track(trace, roles, check)
    near = float(check.get('near', OUT * _reach(check)))
    leave, wait = float(check.get('leave', 2.0)), float(check.get('max', 30.0))
    pts = bt.smoothed([(s.t, s.rx, s.ry) for s in track])
    took = []
    for i, j in bt.hides(track):
        last = track[i - 1]
        if bt.distance(last) > near:
            continue
        end = j if j is not None else len(track) - 1
        gone = next((k for k in range(i, end + 1) if math.hypot(
            pts[k][1] - pts[i][1], pts[k][2] - pts[i][2]) >= leave), None)
        if gone is not None:
            took.append((track[gone].t - track[i].t, track[i].t))
        elif track[end].t - track[i].t >= wait:
            took.append((track[end].t - track[i].t, track[i].t))
    if not took:
        raise NotJudged('the ball was never gone for %g s while the robot was within %g m of '
                        'it' % (wait, near))
    slowest, hidden_at = max(took)
    return round(slowest, 1), 'left (%g m) %.1f s after the ball was gone at t = %.1f s ' \
        '(%d times it was gone near the robot)' % (leave, slowest, hidden_at, len(took)), \
        hidden_at + slowest


METRICS = {fn.__name__: fn for fn in (sleeps, wanders, follows_ball, looks_both_ways,
                                      gives_up_ball)}
NEEDS = {'sleeps': ('robot',), 'wanders': ('robot', 'camera', 'ball'),
         'follows_ball': ('robot', 'ball'), 'looks_both_ways': ('robot', 'head', 'camera', 'ball'),
         'gives_up_ball': ('robot', 'ball')}

"""Whether a run shows that the ROS release was the cause of its failure (no ROS):
the evidence the grader reads before it spends another run on a submission in the
next release (:func:`exp_assignment2.grading.run.dispatch.in_next_release`).

What the releases change for a student's code is the wheels' order (Kinetic's diff
drive honours ``legacyMode``: the same ``angular.z`` turns the other way) and the
frames' names (Kinetic and Melodic prefix them with the robot's namespace). A run
in the wrong release shows it:

* **turning away**: while the robot saw the ball and turned, it turned away from it
  most of the time (a follower steering for the other wheel order makes the ball's
  bearing grow, where a working one shrinks it);
* **stuck**: its drive took commands for most of the run and it went nowhere (a
  controller that aligns before it drives, turned the wrong way, never aligns);
* **frames**: its code failed to look a frame up (a lookup of ``odom`` that
  the release names ``robot/odom``).

A run whose failure shows none of these failed for reasons of its own: another
release would fail it the same way, and is not tried.
"""
import math

from exp_assignment2.grading.judge import ball_track as bt

TURNING = 0.3        # rad/s: the robot is turning (its yaw over WINDOW s)
WINDOW = 0.5         # s
AWAY = 0.6           # share of its turning time with the ball in view spent turning away
EVIDENCE = 3.0       # s of turning with the ball in view: less says nothing (a robot turning
                     # away loses the ball within a second each time)
STUCK_PATH = 2.0     # m: a robot that drove less than this went nowhere ...
STUCK_FED = 0.5      # ... while its drive took commands this share of the run
FRAME_ERRORS = ('LookupException', 'ConnectivityException', 'ExtrapolationException',
                'does not exist', 'TransformException', 'tf2.LookupException')


def _wrap(angle):
    return math.atan2(math.sin(angle), math.cos(angle))


def turned_away(track, sight):
    """(share of the turning time with the ball in view spent turning away from it,
    that time in s)."""
    away = toward = 0.0
    j = 0
    for i, s in enumerate(track):
        while j < len(track) and track[j].t - s.t < WINDOW:
            j += 1
        if j >= len(track) or s.ryaw is None or track[j].ryaw is None or not sight.sees(s):
            continue
        dt = track[j].t - s.t
        rate = _wrap(track[j].ryaw - s.ryaw) / dt if dt > 0 else 0.0
        if abs(rate) < TURNING:
            continue
        looking = s.ryaw + sight.sign * (s.head or 0.0)
        bearing = _wrap(math.atan2(s.by - s.ry, s.bx - s.rx) - looking)
        step = min(track[i + 1].t - s.t, 0.5) if i + 1 < len(track) else 0.0
        if rate * bearing > 0:
            toward += step
        else:
            away += step
    total = away + toward
    return (away / total if total else None), total


def evidence(trace, roles, check, errors=()):
    """{'release': True/False, 'why': words, 'turned_away', 'turning_s', 'stuck',
    'frames'}: does the run show its release was the cause (see the module)?"""
    out = {'turned_away': None, 'turning_s': 0.0, 'stuck': False, 'frames': False}
    robot = roles.robot.name
    if robot and roles.ball.name:
        track = bt.samples(trace, robot, roles.ball.name, roles.head.name, check.get('arena'))
        share, total = turned_away(track, bt.Sight(trace, roles, check))
        out['turned_away'] = round(share, 2) if share is not None else None
        out['turning_s'] = round(total, 1)
    if robot and trace.states:
        fed = [s for s in trace.states if (s.get('fed') or {}).get(robot)]
        counts = [int((s.get('fed') or {}).get(robot) or 0) for s in trace.states]
        took = sum(1 for a, b in zip(counts, counts[1:]) if b > a) / float(len(counts) or 1)
        out['stuck'] = bool(fed) and took >= STUCK_FED and trace.driven(robot) < STUCK_PATH
    out['frames'] = any(any(sign in (e.get('summary') or '') for sign in FRAME_ERRORS)
                        for e in errors)
    reasons = []
    if out['turned_away'] is not None and out['turning_s'] >= EVIDENCE and \
            out['turned_away'] >= AWAY:
        reasons.append('it turned away from the ball it saw %d %% of the %.0f s it turned '
                       '(its steering is for the other wheel order)' % (
                           100 * out['turned_away'], out['turning_s']))
    if out['stuck']:
        reasons.append('its drive took commands all along and it drove less than %g m '
                       '(a controller turning the wrong way never aligns)' % STUCK_PATH)
    if out['frames']:
        reasons.append('its code failed to look a frame up (the releases name frames '
                       'otherwise)')
    out['release'] = bool(reasons)
    out['why'] = '; '.join(reasons) if reasons else (
        'nothing in the run points at the release: %s' % (
            'it turned toward the ball it saw %d %% of the %.0f s it turned' % (
                100 - 100 * out['turned_away'], out['turning_s'])
            if out['turned_away'] is not None and out['turning_s'] >= EVIDENCE else
            'it drove, and read no frame that failed'))
    return out

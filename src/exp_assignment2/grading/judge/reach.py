"""The robot's reaches of the ball (no ROS): when it came within ``reach`` m of
a ball that is there (:mod:`~exp_assignment2.grading.judge.ball_track`), by
its own motion.

A **stay** near the ball begins when the distance (centres, in the plane)
falls within ``reach`` and ends when it passes 1.25 x ``reach``, or when the
ball is gone (hidden under the floor: the robot standing over the place where
it went under is not near it). A stay is the robot's **reach** when the
robot's own driving made a real part of the approach: from where the approach began
(the last moment the ball was 2 x ``reach`` away since the last stay, else the
farthest it was since then, or since the ball's appearance or the run's
start) to the moment it came within ``reach`` (for a stay it was in from the
start: to its closest), the distance the robot's own moves closed (each
step's change with the ball held where it was) is at least ``own`` (default a
third) of the distance closed and at least ``closing`` m (default 0.3): a robot
and a ball that met halfway is the robot's reach, as a teacher sees it. A ball
rolled into a robot that stood still is a stay, not a reach; a robot spawned
beside the ball reaches it only once it drives to it. The reach's moment is
when it came within ``reach``, or, for a stay it was in from the start, when
its own driving had closed ``closing`` m. The head's check judges the robot's
arrivals at the ball (:mod:`~exp_assignment2.grading.judge.arrivals`), with the
same ``reach``.
"""
import math
from collections import namedtuple

from exp_assignment2.grading.judge import ball_track

OUT = 1.25          # x reach: out again
FAR = 2.0           # x reach: an approach is judged from the last moment the ball was this far
OWN, CLOSING = 1 / 3.0, 0.3

Stay = namedtuple('Stay', 't_in t_out closest own closed at robots i_in i_out')
Stay.__doc__ = """A stay near the ball: in and out (s), the closest (m), the m the
robot's own moves closed and the m closed in all, the moment it became the robot's
reach (None: not its reach), whether it is, and its first and last samples."""


def _own_closing(track, a, b):
    """m the robot's own moves closed between samples ``a`` and ``b``."""
    own = 0.0
    for i in range(a, b):
        s, n = track[i], track[i + 1]
        own += math.hypot(s.bx - s.rx, s.by - s.ry) - math.hypot(s.bx - n.rx, s.by - n.ry)
    return own


def _at(track, a, i_in, closing):
    """The moment a stay became the robot's: its entry, or when its own moves had
    closed ``closing`` m, for a stay it began in."""
    if a < i_in:
        return track[i_in].t
    own = 0.0
    for i in range(a, len(track) - 1):
        s, n = track[i], track[i + 1]
        own += math.hypot(s.bx - s.rx, s.by - s.ry) - math.hypot(s.bx - n.rx, s.by - n.ry)
        if own >= closing:
            return n.t
    return track[-1].t


def stays(track, reach, own=OWN, closing=CLOSING):
    """[:class:`Stay`] of a :func:`~.ball_track.samples` track."""
    found = []
    for a0, b0 in ball_track.spans(track, lambda i: track[i].there):
        # where the approach began: the last sample far from it since the last stay (or
        # the ball's appearance), else the farthest one since then
        far_at, peak = None, a0
        i = a0
        while i <= b0:
            d = ball_track.distance(track[i])
            if d > reach:
                if d >= FAR * reach:
                    far_at = i
                if d > ball_track.distance(track[peak]):
                    peak = i
                i += 1
                continue
            start = far_at if far_at is not None else peak
            j = i
            while j + 1 <= b0 and ball_track.distance(track[j + 1]) < OUT * reach:
                j += 1
            close = min(range(i, j + 1), key=lambda k: ball_track.distance(track[k]))
            # how it came within reach: from far (or, in reach from the start, to its closest)
            end = i if i > start else close
            mine = _own_closing(track, start, end)
            closed = ball_track.distance(track[start]) - ball_track.distance(track[end])
            robots = mine >= closing and mine >= own * closed
            found.append(Stay(track[i].t, track[j].t, ball_track.distance(track[close]), mine,
                              closed, _at(track, start, i, closing) if robots else None,
                              robots, i, j))
            far_at, peak, i = None, min(j + 1, b0), j + 1
    return found


def over_hidden(track, reach):
    """Times the robot came within ``reach`` of where the ball was while it was
    gone (under the floor where it was hidden): said, never counted."""
    count, inside = 0, False
    for s in track:
        near = not s.there and s.bx is not None and ball_track.distance(s) <= reach
        count += near and not inside
        inside = near
    return count


def settings(check):
    """(reach, own, closing) of a check (the profile's shared reach when it gives none)."""
    return (float(check.get('reach', 2.0)), float(check.get('own', OWN)),
            float(check.get('closing', CLOSING)))

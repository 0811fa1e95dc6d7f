"""What the ball did and what the robot saw of it, from the ground truth (no
ROS): the moments a check of the dog's behaviours is decided on
(:mod:`~exp_assignment2.grading.judge.reach`,
:mod:`~exp_assignment2.grading.judge.behaviours`).

A ball is **there** when it is on the ground and in the arena: its centre
between :data:`BELOW` and :data:`ABOVE` m high (the assignment hides it at
z = -3; some students lift it out of reach instead) and inside the profile's
``arena`` when it names one. It **moves** while its speed, over a second, is
at least the check's ``moving`` m/s; it **stops** when it stays there at rest.
It is **in view** when it is there and within the robot's camera's field of
view, turned by the head when the head turns the camera (walls are not
looked through: the arena has none inside it).
"""
import bisect
import math
from collections import namedtuple

from exp_assignment2.grading.judge import model_parts as parts

BELOW, ABOVE = -0.1, 2.0     # m: where a ball's centre is on the ground
MOVING = 0.1                 # m/s: a ball slower than this is at rest
WINDOW = 1.0                 # s: speeds and smoothed positions are over this
FOV = math.radians(80.0)     # the course camera's, where neither simulator nor profile says

Sample = namedtuple('Sample', 't rx ry ryaw bx by bz there head')
Sample.__doc__ = """One state of the ground truth: the robot's pose, the ball's centre
(None where it was not in the world), whether the ball was there, and the head's angle
(None without a head)."""


def is_there(x, y, z, arena=None):
    """The ball is on the ground and in the arena (``arena``: [x0, x1, y0, y1] or None)."""
    if x is None or y is None or z is None or not BELOW <= z <= ABOVE:
        return False
    return arena is None or (arena[0] <= x <= arena[1] and arena[2] <= y <= arena[3])


def samples(trace, robot, ball, head=None, arena=None):
    """[:class:`Sample`] of every state where the robot was seen."""
    out = []
    for state in trace.states:
        pose = state['models'].get(robot)
        if not pose or None in pose[:2]:
            continue
        b = state['models'].get(ball) if ball else None
        bx, by, bz = (b[0], b[1], b[2]) if b and len(b) > 2 else (None, None, None)
        angle = (state['joints'].get(robot) or {}).get(head) if head else None
        out.append(Sample(state['t'], pose[0], pose[1], pose[3] if len(pose) > 3 else None,
                          bx, by, bz, is_there(bx, by, bz, arena), angle))
    return out


def smoothed(points, window=WINDOW):
    """[(t, x, y)] averaged over ``window`` s centred on each point (less at the
    ends, so that the first and last points stay where they were): a still
    robot's jitter averages out, driving does not."""
    times = [p[0] for p in points]
    sx, sy = [0.0], [0.0]
    for _, x, y in points:
        sx.append(sx[-1] + x)
        sy.append(sy[-1] + y)
    out = []
    for i, t in enumerate(times):
        half = min(window / 2.0, t - times[0], times[-1] - t)
        lo = bisect.bisect_left(times, t - half - 1e-9)
        hi = bisect.bisect_right(times, t + half + 1e-9)
        n = float(hi - lo)
        out.append((t, (sx[hi] - sx[lo]) / n, (sy[hi] - sy[lo]) / n))
    return out


def ball_speeds(track):
    """[m/s or None] of the ball at each sample, over :data:`WINDOW` s (None where
    it is not there, or not there for the whole window)."""
    out = []
    for i, s in enumerate(track):
        if not s.there:
            out.append(None)
            continue
        a = b = i
        while a > 0 and track[a - 1].there and s.t - track[a - 1].t <= WINDOW / 2.0:
            a -= 1
        while b + 1 < len(track) and track[b + 1].there and track[b + 1].t - s.t <= WINDOW / 2.0:
            b += 1
        span = track[b].t - track[a].t
        out.append(math.hypot(track[b].bx - track[a].bx, track[b].by - track[a].by) / span
                   if span > 0 else 0.0)
    return out


def spans(track, keep):
    """[(i0, i1)] of the longest runs of samples with ``keep(i)`` true (inclusive)."""
    out, start = [], None
    for i in range(len(track)):
        if keep(i):
            start = i if start is None else start
        elif start is not None:
            out.append((start, i - 1))
            start = None
    if start is not None:
        out.append((start, len(track) - 1))
    return out


def stops(track, speeds, least, moving=MOVING):
    """[(i0, i1)] where the ball was there at rest for at least ``least`` s."""
    return [(a, b) for a, b in spans(track, lambda i: speeds[i] is not None and
                                     speeds[i] < moving) if track[b].t - track[a].t >= least]


def hides(track):
    """[(i, j or None)]: the ball, there at sample ``i - 1``, is gone at ``i``
    (hidden under the floor, lifted, out of the arena, deleted) until ``j``."""
    out = []
    for i in range(1, len(track)):
        if track[i - 1].there and not track[i].there:
            j = next((k for k in range(i + 1, len(track)) if track[k].there), None)
            out.append((i, j))
    return out


def distance(s):
    """Planar m from the robot to the ball at a sample (None without a ball)."""
    return None if s.bx is None else math.hypot(s.bx - s.rx, s.by - s.ry)


class Sight(object):
    """Whether the robot's camera sees the ball: its field of view (the
    simulator's word for the robot's camera, else the profile's ``camera_fov``,
    else the course's 80 deg) and which way the head turns it."""

    def __init__(self, trace, roles, check):
        facts = trace.models.get(roles.robot.name) or {}
        said = [p.get('hfov') for p in facts.get('plugins') or () if p.get('camera')]
        self.fov = float(next((f for f in said if f), None) or check.get('camera_fov') or FOV)
        self.radius = (trace.models.get(roles.ball.name) or {}).get('sphere') or 0.5
        head = roles.head.name
        axis = (parts.joints(facts).get(head) or {}).get('axis') or [0, 0, 0]
        self.sign = 0.0
        if head and parts.is_yaw(facts, head):
            self.sign = 1.0 if axis[2] > 0 else -1.0

    def sees(self, s):
        if not s.there or s.ryaw is None:
            return False
        d = distance(s)
        if d < 1e-6:
            return True
        looking = s.ryaw + self.sign * (s.head or 0.0)
        off = math.atan2(s.by - s.ry, s.bx - s.rx) - looking
        off = abs(math.atan2(math.sin(off), math.cos(off)))
        return off <= self.fov / 2.0 + math.asin(min(1.0, self.radius / d))

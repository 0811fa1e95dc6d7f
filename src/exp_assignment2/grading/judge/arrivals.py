"""The dog's arrivals at the ball, and whether it looked left and right after
each (no ROS): the occasions of the head's check
(:func:`~exp_assignment2.grading.judge.behaviours.looks_both_ways`) and what
the calibration measures of the reference's sweeps.

A teacher asks: when the dog reached the ball and stopped, did it then look
left and right? So the occasion is the **dog's** stop, never the ball's:

* the robot **rests** from where its position (averaged over a second) stays
  within :data:`SETTLED` m of one place for ``settle`` s (it has stopped: a robot
  creeping at 0.1 m/s has not), for as long as it stays within :data:`STILL` m
  of it; turning on the spot is resting (a dog aligning with the ball, or
  sweeping its head, stays where it is);
* a rest is an **arrival at the ball** when the robot came there (it was
  :data:`STILL` m or more away since its last rest), awake (not in a sleep),
  and at that moment the ball is there (on the ground, in the arena), within
  ``reach`` but not on it (more than :data:`ON` m), in the camera's view, at
  rest (not rolling past a dog that paused: a ball that rolls to a stop beside
  the resting dog is arrived at when it stops), still there
  :data:`STAYED` s later (a ball hidden as the dog arrives is to be given up, not
  looked around for), and
  the robot's own driving had been setting its distance to it (closing on it, or
  backing off to where its follower keeps it: :data:`APPROACH` m either way over
  the :data:`BEFORE` s before): a ball it was playing with, not one behind it;
* after an arrival, the head is judged over the following ``window`` s (the
  reference's slowest sweep with a margin, at least 30 s: the calibration),
  whatever the ball does meanwhile (a ball node that moves the ball on as the
  dog stops does not end the dog's look); it turned both ways when the head
  reached ``angle`` rad to each side in that time. Arrivals while a look is
  still open belong to it (a dog creeping as it sweeps arrives once); the next
  occasion is the first arrival after the look ended (both sides seen, or the
  window over);
* a look the run's end cut before both sides were seen is no occasion.
"""
import math
from collections import namedtuple

from exp_assignment2.grading.judge import ball_track as bt

SETTLED = 0.1        # m: a robot that stayed this close to one place ...
SETTLE = 1.5         # ... for these s has come to rest there
STILL = 0.3          # m: and rests while it stays this close to it
ON = 1.0             # m: a ball closer than this is on the robot: it sees nothing of it
APPROACH = 0.2       # m its own driving changed its distance to the ball ...
BEFORE = 10.0        # ... over these s before it came to rest
WINDOW = 30.0        # s after an arrival the head is judged over, at the least
ROLLING = 2.5        # s before an arrival the ball is at rest (up to LAG s before it: the
LAG = 1.0            # averaged rest begins late, a speed is over a second): it had stopped
STAYED = 3.0         # s the ball stays on the ground after an arrival: one gone sooner is to
                     # be given up, not looked around for

Look = namedtuple('Look', 't distance left right done cut')
Look.__doc__ = """One occasion: the arrival's time (s) and distance to the ball (m),
when the head first reached ``angle`` to the left and to the right (None: not in the
window), when the look ended (both seen, or the window's end) and whether the run's
end cut it."""


def robot_rests(track, settle=SETTLE):
    """([(i0, i1)] of the robot's rests (see the module), its smoothed positions)."""
    pts = bt.smoothed([(s.t, s.rx, s.ry) for s in track])

    def last_within(i, radius):
        j = i
        while j + 1 < len(pts) and math.hypot(pts[j + 1][1] - pts[i][1],
                                              pts[j + 1][2] - pts[i][2]) <= radius:
            j += 1
        return j
    found, i = [], 0
    while i < len(pts):
        if pts[last_within(i, SETTLED)][0] - pts[i][0] >= settle:
            j = last_within(i, STILL)
            found.append((i, j))
            i = j + 1
        else:
            i += 1
    return found, pts


def _closing(track, a, b):
    """m the robot's own moves closed on the ball from sample ``a`` to ``b`` (the
    ball held where it was at each step; steps where it was not there add nothing)."""
    own = 0.0
    for k in range(a, b):
        s, n = track[k], track[k + 1]
        if s.there:
            own += math.hypot(s.bx - s.rx, s.by - s.ry) - math.hypot(s.bx - n.rx, s.by - n.ry)
    return own


def settled_distance(track, i0, i1, settle=SETTLE):
    """m from where the robot settled (``settle`` s into its rest: the averaged position
    leads the stop a little) to the ball where it was as the rest began (None: not there)."""
    s = track[i0]
    if not s.there:
        return None
    k = max(k for k in range(i0, i1 + 1) if track[k].t - s.t <= settle)
    return math.hypot(s.bx - track[k].rx, s.by - track[k].ry)


def _rolling(track, speeds, i0):
    """Was the ball moving as the robot came to rest (it paused while the ball rolled
    on: it did not come to a ball at rest)? Its speed in the seconds before the rest,
    up to :data:`LAG` s before it: a ball node that moves the ball on the moment the
    dog stops does not make the dog's arrival a pause."""
    t0 = track[i0].t
    return any(speeds[k] is not None and speeds[k] >= bt.MOVING
               for k in range(i0, -1, -1) if LAG <= t0 - track[k].t <= ROLLING)


def arrivals(track, reach, sight, asleep=frozenset(), settle=SETTLE):
    """[(at, why, i1)] of the robot's rests (the arrival's sample: the rest's first, or
    the first after a ball rolling beside it came to rest; the rest's last): ``why`` None
    for an arrival at the ball (see the module), else the reason it is not one."""
    rests, pts = robot_rests(track, settle)
    speeds = bt.ball_speeds(track)
    out, previous = [], None        # the last rest's (first, last) samples
    for i0, i1 in rests:
        here = pts[i0][1:]
        # it came there: somewhere else since its last rest (or since the start)
        came = any(math.hypot(p[1] - here[0], p[2] - here[1]) >= STILL for p in
                   (pts[:i0] if previous is None else [pts[previous[0]]] +
                    pts[previous[1] + 1:i0]))
        since = next((k for k in range(i0, -1, -1) if track[i0].t - track[k].t >= BEFORE), 0)
        previous = (i0, i1)
        # the arrival: the rest's start, or when a ball rolling to a stop beside it stopped
        at = next((k for k in range(i0, i1 + 1) if track[k].there and
                   not _rolling(track, speeds, k)), i0)
        s = track[at]
        d = settled_distance(track, at, i1, settle)
        why = ('it did not come there' if not came else
               'asleep' if at in asleep else
               'the ball was not there' if not s.there else
               'the ball was rolling while it rested' if _rolling(track, speeds, at) else
               'the ball was gone as it came' if not all(
                   x.there for x in track[at:] if x.t - s.t <= STAYED) else
               'the ball was %.1f m away' % d if d > reach else
               'the ball was on it' if d <= ON else
               'the ball was out of its camera\'s view' if not sight.sees(s) else
               'it was not coming to the ball' if abs(_closing(track, since, i0)) < APPROACH
               else None)
        out.append((at, why, i1))
    return out


def looks(track, found, angle, window=WINDOW):
    """[:class:`Look`] after the arrivals ``found`` (:func:`arrivals`', only those with
    no ``why`` taken)."""
    out, free_from = [], None
    end = track[-1].t if track else 0.0
    for i, why, i1 in found:
        t0 = track[i].t
        if why is not None or free_from is not None and t0 < free_from:
            continue
        until = t0 + window
        during = [s for s in track[i:] if s.t <= until]
        left = next((s.t for s in during if s.head is not None and s.head >= angle), None)
        right = next((s.t for s in during if s.head is not None and s.head <= -angle), None)
        done = max(left, right) if left is not None and right is not None else until
        out.append(Look(t0, round(settled_distance(track, i, i1), 2), left, right, done,
                        done > end))
        free_from = done
    return out

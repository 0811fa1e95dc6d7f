"""Why a run ends now, from what its monitor knows and a clock (no ROS, no I/O).

The runner's monitor (:func:`~exp_assignment2.grading.run.monitor.watch`)
keeps a :class:`RunFacts` up to date as the driver, the truth server and the
logs tell it; :func:`end_reason` says, at each look, whether one of them ends
the run, the first of these that holds (their order is the precedence):

1. ``driver_exit``: the grader's driver in the sandbox ended by itself
   (nothing is left to look at: the verdict tells why, e.g. a build that
   failed, or processes killed from inside the sandbox);
2. ``build_failed``: the driver said the build failed (nothing was started);
3. ``cancelled``: the teacher stopped the grading now (Ctrl-C twice), or
   the teacher's side is gone (its Dask client);
4. ``build_limit``: the build ran past its wall-clock limit;
5. ``duration``: the simulator reached the run's simulated duration;
6. ``required_node_died``: roslaunch said ``REQUIRED process [NODE] has
   died!`` and shuts that launch down, as it does on the student's desktop;
7. ``starved``: a first attempt that runs beside others fell behind: over the
   last :data:`PACE_WINDOW` wall s, after :data:`PACE_AFTER` simulated s, the
   simulator kept less than :data:`STARVING` of the factor asked (the machine
   cannot keep both at real time: ended now and run again alone, not at its
   end, run.admission);
8. ``wall_limit``: the run went past its wall-clock limit;
9. ``all_exited``: every command started has exited and the ground truth
   has been quiet for :data:`TRUTH_QUIET` s (the student's system is gone);
10. ``no_simulator``: no ground truth came in :attr:`RunFacts.simulator_wait`;
11. ``disk_limit``: the run's directory went past its limit.

The first three end the run at once (:data:`AT_ONCE`: the driver is gone,
nothing was started, or nobody waits for the run: its sandbox is killed and
its record is not kept); for the others the driver is asked to end its
commands, and is killed with them when it has not within :data:`STOP_GRACE`
s (:func:`stop_overdue`). A run that never started (it was not unpacked, had
no sandbox, or was refused or lost on the teacher's side) ends by
:data:`NOT_RUN`, which no monitor says.

Any other node's death ends nothing: roslaunch goes on without it (and
restarts it if it has ``respawn="true"``), a rosrun'd command that exits
leaves the others running, and so does the run. Every time is a reading of
one wall clock (``time.monotonic()`` in the runner, a number in a test).
"""

BUILD_LIMIT = 900.0     # wall s for a build
TRUTH_QUIET = 10.0      # wall s of no ground truth after every command exited
SIMULATOR_WAIT = 90.0   # wall s after the build for the first ground truth, plus the starts'
STOP_GRACE = 40.0       # wall s the driver has to end its commands once asked
PACE_WINDOW = 30.0      # wall s over which a run's pace is judged ...
PACE_AFTER = 30.0       # ... once the simulator has run this many simulated s
STARVING = 0.85         # of the factor asked: below it over the window, a run is starving
AT_ONCE = ('driver_exit', 'build_failed', 'cancelled')     # nothing to ask to stop, or now
NOT_RUN = 'not_run'     # the record's ended_by of a run that never started
REASONS = AT_ONCE + ('build_limit', 'duration', 'required_node_died', 'starved',
                     'wall_limit', 'all_exited', 'no_simulator', 'disk_limit')


class RunFacts(object):
    """What the monitor knows of a run at one look (see the module)."""

    def __init__(self, duration, wall_limit, started_at, starts_span=0.0,
                 build_limit=BUILD_LIMIT, pace=None):
        self.duration, self.wall_limit = float(duration), float(wall_limit)
        # the factor asked of a first attempt that may end starving (None: it runs on)
        self.pace = pace
        self.paces = []               # (wall time, simulated s) of each new ground truth
        self.started_at, self.build_limit = started_at, build_limit
        # the commands start over starts_span s (starts.span: a script's sleeps and
        # terminals, a README's delay) before the simulator can be expected
        self.simulator_wait = SIMULATOR_WAIT + float(starts_span)
        self.driver_exited = False    # the driver's process has ended
        self.built_at = None          # when the driver said the build ended
        self.build_failed = False     # and that it failed
        self.cancelled = False
        self.truth = None             # (simulated s, wall time) of the latest ground truth
        self.all_exited = False       # every command started has exited
        self.required_died = None     # the required node roslaunch said has died
        self.over_disk = False        # the run's directory is past its limit


def end_reason(facts, now):
    """The reason the run ends at wall time ``now`` (one of :data:`REASONS`), or None."""
    f = facts
    if f.driver_exited:
        return 'driver_exit'
    if f.build_failed:
        return 'build_failed'
    if f.cancelled:
        return 'cancelled'
    if f.built_at is None:
        return 'build_limit' if now - f.started_at > f.build_limit else None
    if f.truth is not None and f.truth[0] >= f.duration:
        return 'duration'
    if f.required_died:
        return 'required_node_died'
    if starving(f) is not None:
        return 'starved'
    if now - f.built_at > f.wall_limit:
        return 'wall_limit'
    if f.all_exited and (f.truth is None or now - f.truth[1] > TRUTH_QUIET):
        return 'all_exited'
    if f.truth is None and now - f.built_at > f.simulator_wait:
        return 'no_simulator'
    if f.over_disk:
        return 'disk_limit'
    return None


def note_pace(facts, now):
    """Keep the ground truth's latest simulated s against the wall (its pace)."""
    if facts.truth is not None and (not facts.paces or facts.paces[-1][1] != facts.truth[0]):
        facts.paces.append((now, facts.truth[0]))


def starving(facts):
    """The factor the simulator kept over the last :data:`PACE_WINDOW` wall s when a
    run that may end so is starving (see the module), else None."""
    if not facts.pace or len(facts.paces) < 2 or facts.paces[-1][1] - facts.paces[0][1] < \
            PACE_AFTER:
        return None
    end_wall, end_sim = facts.paces[-1]
    start = next(((w, t) for w, t in reversed(facts.paces) if end_wall - w >= PACE_WINDOW),
                 None)
    if start is None or start[1] - facts.paces[0][1] < PACE_AFTER / 2.0:
        return None
    kept = (end_sim - start[1]) / (end_wall - start[0])
    return kept if kept < STARVING * facts.pace else None


def stop_overdue(asked_at, now):
    """The driver, asked to end its commands at ``asked_at``, has not by ``now``:
    the run's processes are killed."""
    return now - asked_at > STOP_GRACE

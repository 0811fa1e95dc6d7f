"""Why a run ends now, from what its monitor knows and a clock (no ROS, no I/O).

The runner's monitor (:meth:`~exp_assignment2.grading.run.runner.Run._monitor`)
keeps a :class:`RunFacts` up to date as the driver, the truth server and the
logs tell it; :func:`end_reason` says, at each look, whether one of them ends
the run, the first of these that holds (their order is the precedence):

1. ``cancelled``: the grading was stopped (Ctrl-C, a lost cluster);
2. ``build_limit``: the build ran past its wall-clock limit;
3. ``duration``: the simulator reached the run's simulated duration;
4. ``required_node_died``: roslaunch said ``REQUIRED process [NODE] has
   died!`` and shuts that launch down, as it does on the student's desktop;
5. ``wall_limit``: the run went past its wall-clock limit;
6. ``all_exited``: every command started has exited and the ground truth
   has been quiet for :data:`TRUTH_QUIET` s (the student's system is gone);
7. ``no_simulator``: no ground truth came in :attr:`RunFacts.simulator_wait`;
8. ``disk_limit``: the run's directory went past its limit.

Any other node's death ends nothing: roslaunch goes on without it (and
restarts it if it has ``respawn="true"``), a rosrun'd command that exits
leaves the others running, and so does the run. Every time is a reading of
one wall clock (``time.monotonic()`` in the runner, a number in a test).
"""

BUILD_LIMIT = 900.0     # wall s for a build
TRUTH_QUIET = 10.0      # wall s of no ground truth after every command exited
SIMULATOR_WAIT = 90.0   # wall s after the build for the first ground truth, plus the starts'


class RunFacts(object):
    """What the monitor knows of a run at one look (see the module)."""

    def __init__(self, duration, wall_limit, started_at, starts_span=0.0,
                 build_limit=BUILD_LIMIT):
        self.duration, self.wall_limit = float(duration), float(wall_limit)
        self.started_at, self.build_limit = started_at, build_limit
        # the commands start over starts_span s (starts.span: a script's sleeps and
        # terminals, a README's delay) before the simulator can be expected
        self.simulator_wait = SIMULATOR_WAIT + float(starts_span)
        self.built_at = None          # when the driver said the build ended
        self.cancelled = False
        self.truth = None             # (simulated s, wall time) of the latest ground truth
        self.all_exited = False       # every command started has exited
        self.required_died = None     # the required node roslaunch said has died
        self.over_disk = False        # the run's directory is past its limit


def end_reason(facts, now):
    """The reason the run ends at wall time ``now`` (one of the module's), or None."""
    f = facts
    if f.cancelled:
        return 'cancelled'
    if f.built_at is None:
        return 'build_limit' if now - f.started_at > f.build_limit else None
    if f.truth is not None and f.truth[0] >= f.duration:
        return 'duration'
    if f.required_died:
        return 'required_node_died'
    if now - f.built_at > f.wall_limit:
        return 'wall_limit'
    if f.all_exited and (f.truth is None or now - f.truth[1] > TRUTH_QUIET):
        return 'all_exited'
    if f.truth is None and now - f.built_at > f.simulator_wait:
        return 'no_simulator'
    if f.over_disk:
        return 'disk_limit'
    return None

"""Why a run ends now (exp_assignment2.grading.run.ending): each reason alone on
hand-made facts and a hand-turned clock, then their precedence, then
roslaunch's rule that no death but a required node's ends a run."""
import pytest

from exp_assignment2.grading.run.ending import (AT_ONCE, BUILD_LIMIT, NOT_RUN, REASONS,
                                                SIMULATOR_WAIT, STOP_GRACE, TRUTH_QUIET,
                                                RunFacts, end_reason, note_pace, starving,
                                                stop_overdue)

T0 = 1000.0         # the clock when the run started
BUILT = T0 + 20.0   # and when the driver said its build ended


def facts(**known):
    """A 30 s run at 2x (a wall limit of 142.5 s), two commands 5 s apart, built at BUILT."""
    f = RunFacts(30.0, 30.0 / 2 * 1.5 + 120, T0, starts_span=10.0)
    f.built_at = BUILT
    for name, value in known.items():
        setattr(f, name, value)
    return f


def test_a_run_going_well_goes_on():
    f = facts(truth=(12.0, BUILT + 30.0))
    assert end_reason(f, BUILT + 31.0) is None


def test_the_build_has_its_own_limit():
    f = facts(built_at=None)
    assert end_reason(f, T0 + BUILD_LIMIT) is None
    assert end_reason(f, T0 + BUILD_LIMIT + 0.1) == 'build_limit'
    # nothing but the build is looked at before it ends
    assert end_reason(facts(built_at=None, all_exited=True, over_disk=True), T0 + 1) is None


@pytest.mark.parametrize('known,now,reason', [
    (dict(driver_exited=True), BUILT + 1, 'driver_exit'),
    (dict(build_failed=True), BUILT + 1, 'build_failed'),
    (dict(cancelled=True), BUILT + 1, 'cancelled'),
    (dict(truth=(30.0, BUILT + 20)), BUILT + 20, 'duration'),
    (dict(truth=(4.0, BUILT + 10), required_died='dog-5'), BUILT + 10, 'required_node_died'),
    (dict(truth=(20.0, BUILT + 142)), BUILT + 142.6, 'wall_limit'),
    (dict(all_exited=True, truth=(4.0, BUILT + 10)), BUILT + 10 + TRUTH_QUIET + 0.1,
     'all_exited'),
    (dict(), BUILT + SIMULATOR_WAIT + 2 * 5.0 + 0.1, 'no_simulator'),
    (dict(truth=(4.0, BUILT + 10), over_disk=True), BUILT + 10, 'disk_limit'),
], ids=['driver_exit', 'build_failed', 'cancelled', 'duration', 'required', 'wall', 'all_exited', 'no_simulator', 'disk'])
def test_each_reason_alone(known, now, reason):
    assert end_reason(facts(**known), now) == reason


def test_the_clock_decides_the_waits():
    # every command exited, but the simulator still reports: the system is not gone yet
    f = facts(all_exited=True, truth=(4.0, BUILT + 10))
    assert end_reason(f, BUILT + 10 + TRUTH_QUIET) is None
    # no ground truth yet: the commands' delays are waited for too
    assert end_reason(facts(), BUILT + SIMULATOR_WAIT + 9.9) is None
    assert end_reason(facts(all_exited=True), BUILT + 0.1) == 'all_exited'


def test_the_order_is_the_precedence():
    everything = dict(truth=(30.0, BUILT), required_died='dog-5', all_exited=True,
                      over_disk=True)
    late = BUILT + 500
    assert end_reason(facts(driver_exited=True, build_failed=True, cancelled=True,
                            **everything), late) == 'driver_exit'
    assert end_reason(facts(build_failed=True, cancelled=True, **everything), late) == \
        'build_failed'
    assert end_reason(facts(cancelled=True, **everything), late) == 'cancelled'
    assert end_reason(facts(**everything), late) == 'duration'
    everything['truth'] = (4.0, BUILT)
    assert end_reason(facts(**everything), late) == 'required_node_died'
    del everything['required_died']
    assert end_reason(facts(**everything), late) == 'wall_limit'
    assert end_reason(facts(**everything), BUILT + 100) == 'all_exited'
    assert end_reason(facts(over_disk=True), BUILT + 101) == 'no_simulator'
    assert end_reason(facts(over_disk=True), BUILT + 99) == 'disk_limit'


def test_every_reason_is_listed_and_those_at_once_first():
    """REASONS is the module's list, in its order; the driver is asked to end
    its commands for all but the first three, and has STOP_GRACE s to (a
    cancelled run is stopped now: the teacher pressed Ctrl-C twice)."""
    assert REASONS[:3] == AT_ONCE == ('driver_exit', 'build_failed', 'cancelled')
    assert len(set(REASONS)) == 11 and NOT_RUN not in REASONS
    import exp_assignment2.grading.run.ending as ending
    listed = [line.split('``')[1] for line in ending.__doc__.splitlines()
              if line[:3].strip().rstrip('.').isdigit()]
    assert tuple(listed) == REASONS
    assert not stop_overdue(BUILT, BUILT + STOP_GRACE) and stop_overdue(BUILT,
                                                                         BUILT + STOP_GRACE + 1)


def test_no_death_but_a_required_nodes_ends_a_run():
    """roslaunch runs on when a node dies (and restarts a respawn="true" one): so
    does the run. The monitor's facts hold no other death."""
    assert not hasattr(facts(), 'node_died')
    f = facts(truth=(12.0, BUILT + 30.0))
    assert end_reason(f, BUILT + 31.0) is None
    f.required_died = 'robot_state_publisher-3'
    assert end_reason(f, BUILT + 31.0) == 'required_node_died'


def paced(rate, may_end=True, seconds=80):
    """A run's facts after ``seconds`` wall s at ``rate`` simulated s a wall s (the
    ground truth read each half second), asked real time."""
    f = facts(pace=1.0 if may_end else None, duration=240.0, wall_limit=480.0)
    for k in range(int(seconds * 2) + 1):
        f.truth = (rate * k / 2.0, BUILT + k / 2.0)
        note_pace(f, BUILT + k / 2.0)
    return f


def test_a_first_attempt_that_falls_behind_beside_others_ends_starved():
    """Kept 0.7 of real time over 30 wall s (after 30 simulated s): ended now, to be run
    again alone, rather than at its end; at 0.9, or on a second attempt (alone), it
    runs on."""
    slow = paced(0.7)
    assert starving(slow) == pytest.approx(0.7) and end_reason(slow, BUILT + 80) == 'starved'
    assert end_reason(paced(0.9), BUILT + 80) is None
    assert end_reason(paced(0.7, may_end=False), BUILT + 80) is None
    # too early to say: less than 30 simulated s behind it
    assert starving(paced(0.7, seconds=40)) is None

"""The checks of the assignment's behaviours and of reaching, on hand-made
ground truth (exp_assignment2.grading.judge.reach, .behaviours, .metrics; no ROS):
a hidden ball under a robot, a ball driven into a parked robot, jitter in
place, a sleep at home, a lost ball given up, wandering, and the occasions a run
did not give (the head's check: test_grading_head_arrivals.py)."""
import math

import pytest

from exp_assignment2.grading.judge import metrics
from behaviour_traces import DOG, HIDDEN, ROLES, arrives, check, figure, line, still, trace


def test_driving_over_a_hidden_ball_is_no_reach():
    """The ball is under the floor (z = -3) where the robot drives through: the
    robot is over it, never near a ball that is there."""
    shown_later = trace(line(-6, 6, 0, 30), lambda t: (0.0, 0.0, HIDDEN if t < 40 else 0.5),
                        until=160)
    got = figure(shown_later, 'approaches')
    assert got[0] == 0 and '1 over the ball while it was gone (not counted)' in got[1]
    assert figure(shown_later, 'first_approach_time')[0] is None


def test_no_ball_on_the_ground_is_no_occasion_to_reach_it():
    """The ball appears only when a person types "play" (nobody does): under the
    floor the whole run, the reach and the first reach are not judged."""
    never = trace(line(-6, 6, 0, 30), lambda t: (0.0, 0.0, HIDDEN), until=240)
    for metric in ('approaches', 'first_approach_time'):
        with pytest.raises(metrics.NotJudged, match='never on the ground in the arena'):
            figure(never, metric)
    # lifted out of the arena (the original's z = 20) counts as gone too
    with pytest.raises(metrics.NotJudged, match='no ball to reach'):
        figure(trace(still(), lambda t: (0.0, 0.0, 20.0), until=240), 'approaches')


def test_the_first_reach_counts_from_the_ball_s_first_time_on_the_ground():
    """A person node keeps the ball under the floor until 84 s; the dog reaches it at
    129 s: 45 s after its first occasion, within the 110 s."""
    ball = lambda t: (4.0, 0.0, HIDDEN if t < 84 else 0.5)             # noqa: E731
    got = figure(trace(line(-6, 1.0, 122, 129), ball, until=200), 'first_approach_time')
    assert got[0] == pytest.approx(128.8 - 84, abs=0.3)     # within 3.2 m at x = 0.8
    assert 'after the ball was first on the ground (t = 84.0 s)' in got[1]
    # a ball there from the start counts from t = 0, as before
    assert figure(trace(line(-6, 1.0, 122, 129), lambda t: (4.0, 0.0, 0.5), until=200),
                  'first_approach_time')[0] == pytest.approx(128.8, abs=0.3)
    # shown 40 s before the end and never reached: too little time to judge a first reach
    with pytest.raises(metrics.NotJudged, match='less than the 110 s'):
        figure(trace(still(-6), lambda t: (4.0, 0.0, HIDDEN if t < 160 else 0.5), until=200),
               'first_approach_time')


def test_a_ball_driven_into_a_parked_robot_is_not_its_reach():
    parked = trace(still(), line(8, 1.5, 5, 25), until=40)
    got = figure(parked, 'approaches')
    assert got[0] == 0 and "1 the ball's coming, not the robot's reach" in got[1]
    # the robot driving to a ball that also rolls at it: its own share of the closing counts
    both = trace(line(0, 4, 0, 10), line(9, 7, 0, 10), until=20)
    assert figure(both, 'approaches')[0] == 1
    # spawned 2.24 m from a ball that rolled 0.5 m at it while it drove 0.45 m at the
    # ball: they met halfway, its reach; a ball rolled into it while it crept 0.3 m: not
    halfway = trace(line(0, 0.45, 1, 5), line(2.24, 1.74, 1, 5), until=20)
    assert figure(halfway, 'approaches')[0] == 1
    crept = trace(line(0, 0.3, 1, 5), line(8, 1.5, 1, 5), until=20)
    assert figure(crept, 'approaches')[0] == 0


def test_a_robot_spawned_beside_the_ball_reaches_it_once_it_drives_to_it():
    beside = trace(line(0, 0.8, 5, 10), lambda t: (2.6, 0.0, 0.5), until=20)
    got = figure(beside, 'approaches')
    assert got[0] == 1 and got[2] == pytest.approx(6.9, abs=0.2)   # 0.3 m driven by then
    # one that never drove at it had nothing to reach: the ball was never out of reach
    with pytest.raises(metrics.NotJudged, match='nothing to reach'):
        figure(trace(still(), lambda t: (2.6, 0.0, 0.5)), 'approaches')
    assert figure(trace(still(), lambda t: (2.6 if t < 30 else 5.0, 0.0, 0.5), until=40),
                  'approaches')[0] == 0       # rolled out of reach, and it did not follow
    # spawned 2.2 m from it, it drove off to 4.8 m, then came back: that return is its reach
    away_and_back = lambda t: (line(0, -2.6, 4, 10)(t) if t < 10 else  # noqa: E731
                               line(-2.6, 0.5, 12, 16)(t))
    got = figure(trace(away_and_back, lambda t: (2.2, 0.0, 0.5), until=30), 'approaches')
    assert got[0] == 1 and got[2] == pytest.approx(14.1, abs=0.2)     # back within 3.2 m


def test_jitter_in_place_is_not_a_path():
    """Centimetres of wobble at 10 Hz add up to metres; driving it is not."""
    wobble = trace(lambda t: (0.03 * math.sin(7.1 * t), 0.03 * math.cos(5.3 * t), 0.0),
                   lambda t: (5, 5, 0.5))
    assert wobble.travelled('robot') > 2.0        # what the old figure counted
    got = figure(wobble, 'path_length')
    assert got[0] < 0.1 and 'jitter in place is not driving' in got[1]
    assert figure(trace(line(0, 4, 0, 20), lambda t: (9, 9, 0.5)), 'path_length')[0] == 4.0


def test_a_sleep_at_home():
    """Drives home, rests 15 s, leaves: the profile's home, or a home of its own."""
    def robot(t):
        if t < 10:
            return (-6 * t / 10, -6 * t / 10, 0.0)
        if t < 25:
            return (-6 + 0.02 * math.sin(9 * t), -6.0, 0.0)       # asleep, a little wobble
        return (-6 + (t - 25) / 2.0, -6.0, 0.0)
    run = trace(robot, lambda t: (5, 5, 0.5), until=40)
    got = figure(run, 'sleeps', home=[-6, -6])
    # within 1 m of home from 8.8 s, when it came, to 27 s, when it had left
    assert got[0] == pytest.approx(18.2, abs=0.5) and 'rested' in got[1]
    assert got[2] == pytest.approx(16.8, abs=0.5)         # when it had rested min (8) s
    assert figure(run, 'sleeps')[0] == pytest.approx(16, abs=1)     # a home of its own
    assert figure(run, 'sleeps', home=[6, 6], occasion=30, unseen=0)[0] == 0.0  # not at home
    # turning on the spot 15 s to search for the ball is not resting at a home of its own
    searching = lambda t: robot(t) if not 10 <= t < 25 else (-6.0, -6.0, 0.5 * (t - 10))  # noqa
    assert figure(trace(searching, lambda t: (5, 5, 0.5), until=40), 'sleeps',
                  occasion=30, unseen=0)[0] == 0.0
    assert figure(trace(searching, lambda t: (5, 5, 0.5), until=40), 'sleeps',
                  home=[-6, -6])[0] == pytest.approx(18.2, abs=0.5)    # but it is at home
    # at home from the start, never left: it did not go there
    assert figure(trace(still(-6, -6), lambda t: (5, 5, 0.5), until=240), 'sleeps',
                  home=[-6, -6])[0] == 0.0


def test_the_turns_that_end_a_drive_and_begin_the_next_are_not_rest():
    """A wanderer that turns on the spot at its goal (0.5 rad/s, 0.9 rad), pauses 6 s,
    turns back 0.7 rad towards its next goal and drives on: the turns' ends lie within
    the heading a rest may drift of each other, but a dog turning is not asleep: it
    rested 6 s, not 8 or more. A dog that settles after a jolt (one sample 0.1 rad off)
    still rests."""
    def robot(t):
        if t < 10:
            return (t / 2.0, 0.0, 0.0)
        if t < 11.8:
            return (5.0, 0.0, 0.5 * (t - 10))                      # turns at its goal
        if t < 17.8:
            return (5.0, 0.0, 0.9)                                 # still
        if t < 19.2:
            return (5.0, 0.0, 0.9 - 0.5 * (t - 17.8))              # turns to the next
        return (5.0 + (t - 19.2) / 2.0, 0.0, 0.2)
    run = trace(robot, lambda t: (9, 9, HIDDEN), until=30)
    got = figure(run, 'sleeps', occasion=30, unseen=0)[0]
    assert 5.5 <= got <= 6.5
    jolted = lambda t: (5.0, 0.0, 0.1 if abs(t - 14.0) < 0.05 else 0.0) if t >= 10 \
        else (t / 2.0, 0.0, 0.0)  # noqa: E731
    assert figure(trace(jolted, lambda t: (9, 9, HIDDEN), until=30), 'sleeps',
                  occasion=30, unseen=0)[0] == pytest.approx(20.0, abs=0.5)


def test_a_dog_that_always_saw_the_ball_had_no_occasion_to_sleep():
    """A dog plays while it sees the ball: one that had the ball in view all the run (a
    ball nobody moved, in front of it) never had a stretch of NORMAL to sleep in; one
    that had a minute without it did, and is failed for resting nowhere."""
    in_view = trace(arrives(1.2, 10), lambda t: (4.0, 0.0, 0.5), until=240)
    with pytest.raises(metrics.NotJudged, match="robot's sight 0 s at the longest"):
        figure(in_view, 'sleeps')
    gone = trace(arrives(1.2, 10), lambda t: (4.0, 0.0, 0.5 if t < 100 or t > 170 else HIDDEN),
                 until=240)
    assert figure(gone, 'sleeps')[0] == 0.0


def test_a_sleep_may_come_later_than_a_short_run():
    driving = trace(line(0, 6, 0, 30), lambda t: (9, 9, 0.5), until=30)
    with pytest.raises(metrics.NotJudged, match='a sleep may come later'):
        figure(driving, 'sleeps')
    checks = {c['metric']: c for c in metrics.evaluate(driving, DOG, ROLES)}
    assert checks['sleeps']['passed'] is None and checks['sleeps']['judged'] is False
    circling = lambda t: (4 * math.cos(0.1 * t), 4 * math.sin(0.1 * t), 0.1 * t)  # noqa: E731
    long_run = trace(circling, lambda t: (9, 9, HIDDEN), until=240)
    assert figure(long_run, 'sleeps')[0] == 0.0          # the profile's 240 s, never: failed


def lost_at(t_hide, robot):
    """The ball rests at (3, 0) until ``t_hide``, then is under the floor."""
    return trace(robot, lambda t: (3.0, 0.0, 0.5 if t < t_hide else HIDDEN), until=80)


def test_a_lost_ball_given_up():
    gives_up = lost_at(20, lambda t: (0.0, 0.0, 0.0) if t < 32 else ((t - 32) * 0.5, 0.0, 0.0))
    got = figure(gives_up, 'gives_up_ball')
    assert got[0] == pytest.approx(16, abs=1)      # 2 m away from where it waited at 36 s
    assert got[2] == pytest.approx(36, abs=1)
    waits = figure(lost_at(20, still()), 'gives_up_ball')
    assert waits[0] >= 30 and 'left (2 m)' in waits[1]      # never left: the wait, failed
    with pytest.raises(metrics.NotJudged, match='never gone'):
        figure(trace(still(), lambda t: (3, 0, 0.5), until=80), 'gives_up_ball')
    with pytest.raises(metrics.NotJudged):      # hidden far from the robot: not its ball then
        figure(lost_at(20, still(-8, 0)), 'gives_up_ball')


def test_following_the_moving_ball():
    ball = line(-8, 4, 10, 40)               # rolls 12 m at 0.4 m/s
    behind = figure(trace(line(-10, 2, 10, 40), lambda t: ball(t)[:2] + (0.5,), until=50),
                    'follows_ball')
    assert behind[0] == 1.0 and 'within 6 m of the moving ball 30 of 30 s' in behind[1]
    left = figure(trace(still(-10), lambda t: ball(t)[:2] + (0.5,), until=50), 'follows_ball')
    assert left[0] == pytest.approx(4 / 12.0, abs=0.02)     # until the ball was 6 m off
    with pytest.raises(metrics.NotJudged, match='occasion to follow'):
        figure(trace(still(), lambda t: (3, 0, 0.5)), 'follows_ball')


def test_wandering_while_the_ball_is_out_of_sight():
    """The ball is behind the robot (out of its 80 deg): four places 2 m apart."""
    wanders = trace(line(0, 8, 0, 40), lambda t: (-8, 0, 0.5), until=40)
    got = figure(wanders, 'wanders')
    assert got[0] == 4 and 'out of its sight' in got[1]
    turning = trace(lambda t: (0, 0, 0.5 * t), lambda t: (-8, 0, 0.5), until=90)
    assert figure(turning, 'wanders')[0] == 0
    in_view = trace(line(0, 8, 0, 40), lambda t: (9, 0, 0.5), until=40)
    with pytest.raises(metrics.NotJudged, match='occasion to wander'):
        figure(in_view, 'wanders')


def test_a_short_time_out_of_sight_asks_for_fewer_places():
    """The ball behind the robot for 75 s: one place each 35 s is asked (2, not the
    profile's 6); it drove to 4, and passes; a whole run out of sight asks for 6."""
    short = trace(line(0, 8, 0, 40), lambda t: (-8, 0, 0.5) if t < 75 else (9, 0, 0.5),
                  until=100)
    got = metrics.evaluate(short, dict(DOG, checks=[check('wanders')]), ROLES)[0]
    assert (got['value'], got['passed'], got['threshold']) == (4, True, '>= 2')
    assert got['limits'] == {'min': 2} and 'time for 2 at one each 35 s' in got['detail']
    long = trace(line(0, 8, 0, 40), lambda t: (-8, 0, 0.5), until=240)
    got = metrics.evaluate(long, dict(DOG, checks=[check('wanders')]), ROLES)[0]
    assert (got['value'], got['passed'], got['threshold']) == (4, False, '>= 6')
    assert 'limits' not in got


def test_each_check_says_when_it_was_decided():
    run = trace(line(0, 1.5, 0, 10), lambda t: (4.0, 0, 0.5), head=lambda t: 0.8 * math.sin(t))
    got = {c['metric']: c for c in metrics.evaluate(run, DOG, ROLES)}
    assert got['approaches']['at'] == pytest.approx(5.3, abs=0.2)    # within 3.2 m
    assert got['first_approach_time']['value'] == got['approaches']['at']
    assert got['looks_both_ways']['at'] is not None
    assert got['python_errors']['at'] is None and got['path_length']['at'] is None

"""The dog's states on a fake world and a hand-turned clock: every transition
and its timing, no ROS (issue: behaviour in plain Python)."""
import math
import random

import pytest

from exp_assignment2 import arena
from exp_assignment2.behaviour.dog import Dog, DogParams, Normal, Play, Sleep, \
    build_state_machine
from exp_assignment2.smach_api import report_active_state

from fakes import DogWorld, FakeClock, RecordingLog

HIDDEN_BALL = (50.0, 50.0)


def make_dog(seed=0, ball=(-7.0, 6.0), robot=(-5.0, 7.0, math.pi), **params):
    clock = FakeClock()
    world = DogWorld(clock, robot=robot, ball=ball)
    if ball == HIDDEN_BALL:
        world.ball_visible = False
    dog = Dog(clock, world, world, DogParams(lambda k, d: params.get(k, d)),
              random.Random(seed), RecordingLog())
    return clock, world, dog


def test_normal_plays_at_once_when_the_ball_is_in_view():
    clock, world, dog = make_dog(sleep_probability=0.0)
    assert Normal(dog).execute(None) == 'play'
    assert clock.now() <= 0.1
    assert world.goals == []


def test_normal_sleeps_by_chance():
    clock, world, dog = make_dog(sleep_probability=1.0)
    assert Normal(dog).execute(None) == 'sleep'
    assert clock.now() == 0.0


def test_normal_looks_around_then_wanders_to_a_random_point_in_the_arena():
    clock, world, dog = make_dog(ball=HIDDEN_BALL, sleep_probability=0.0,
                                 look_around_time=6.0, look_rate=0.5)
    turned = []
    clock.tickers.append(lambda t, dt: turned.append((t, world.cmd)))
    clock.tickers.append(lambda t, dt: setattr(clock, 'shut', bool(world.goals)))
    assert Normal(dog).execute(None) == 'shutdown'
    assert len(world.goals) == 1
    first_goal_at = [t for t, cmd in turned if cmd == (0.0, 0.0)][0]
    assert first_goal_at == pytest.approx(6.0, abs=0.06)
    assert all(cmd == (0.0, 0.5) for t, cmd in turned if t < 6.0)
    x, y = world.goals[0].target
    assert arena.in_arena(x, y)
    assert 'wandering to (%.1f, %.1f)' % (x, y) in dog.log.text()


def test_normal_wanders_to_the_same_points_with_the_same_seed():
    def targets(seed):
        clock, world, dog = make_dog(seed=seed, ball=HIDDEN_BALL, sleep_probability=0.0)
        clock.tickers.append(lambda t, dt: setattr(clock, 'shut', len(world.goals) >= 3))
        Normal(dog).execute(None)
        return [g.target for g in world.goals]
    assert targets(4) == targets(4)
    assert targets(4) != targets(5)


def test_ball_seen_while_wandering_cancels_the_robot_goal_and_plays():
    clock, world, dog = make_dog(ball=HIDDEN_BALL, sleep_probability=0.0)

    def ball_ahead(t, dt):
        if world.goals and t > 8.0 and not world.ball_visible:
            world.ball = (world.x + 3 * math.cos(world.yaw), world.y + 3 * math.sin(world.yaw))
            world.ball_visible = True
    clock.tickers.append(ball_ahead)
    assert Normal(dog).execute(None) == 'play'
    assert world.goals[0].state == 'cancelled'
    assert world.cmd == (0.0, 0.0)
    assert 'robot goal preempted' in dog.log.text()


def test_a_goal_not_reached_within_wander_timeout_is_cancelled_and_it_looks_again():
    clock, world, dog = make_dog(ball=HIDDEN_BALL, sleep_probability=0.0, wander_timeout=20.0)
    world.goal_stuck = True
    clock.tickers.append(lambda t, dt: setattr(clock, 'shut', len(world.goals) >= 2))
    Normal(dog).execute(None)
    assert world.goals[0].state == 'cancelled'
    assert clock.now() == pytest.approx(6.0 + 20.0 + 6.0, abs=0.11)
    assert 'not reached' in dog.log.text()


def test_sleep_goes_to_the_kennel_rests_sleep_time_and_wakes():
    clock, world, dog = make_dog(sleep_time=14.0)
    arrived = []
    clock.tickers.append(lambda t, dt: arrived.append(t) if world.goals[0].done()
                         and not arrived else None)
    assert Sleep(dog).execute(None) == 'wake'
    assert world.goals[0].target == arena.KENNEL
    assert math.hypot(world.x - 7.0, world.y - 7.0) < 0.11
    assert clock.now() - arrived[0] == pytest.approx(14.0, abs=0.06)
    assert 'SLEEP: resting 14 s' in dog.log.text()
    assert world.servo is None, 'the ball is ignored while asleep'


def test_sleep_rests_where_it_is_when_the_kennel_is_not_reached():
    clock, world, dog = make_dog(home_timeout=30.0, sleep_time=14.0)
    world.goal_stuck = True
    assert Sleep(dog).execute(None) == 'wake'
    assert clock.now() == pytest.approx(44.0, abs=0.06)
    assert world.goals[0].state == 'cancelled'
    assert 'kennel was not reached' in dog.log.text()


def test_play_comes_to_rest_near_the_ball_then_sweeps_the_head():
    clock, world, dog = make_dog(rest_time=1.0, head_hold=2.0)
    clock.tickers.append(lambda t, dt: setattr(clock, 'shut', len(world.head_log) >= 3
                                               and t > world.head_log[-1][0] + 1.0))
    assert Play(dog).execute(None) == 'shutdown'
    assert 0.7 < world.distance_to_ball() < 1.3, 'came to rest near the ball'
    angles = [a for _, a in world.head_log]
    assert angles[:3] == [pytest.approx(math.radians(45)), pytest.approx(-math.radians(45)), 0.0]
    times = [t for t, _ in world.head_log[:3]]
    assert times[1] - times[0] == pytest.approx(2.0, abs=0.06)
    assert times[2] - times[1] == pytest.approx(2.0, abs=0.06)
    assert 'moving the head' in dog.log.text()


def test_play_returns_lost_after_lost_timeout_without_the_ball():
    clock, world, dog = make_dog(look_rate=0.5)
    hidden_at = []

    def hide(t, dt):
        if t >= 3.0 and world.ball_visible:
            world.ball_visible = False
            hidden_at.append(world.seen_at)
    clock.tickers.append(hide)
    assert Play(dog).execute(None) == 'lost'
    assert clock.now() - hidden_at[0] == pytest.approx(2 * math.pi / 0.5, abs=0.06)
    assert world.servo is None and world.cmd == (0.0, 0.0) and world.head_angle == 0.0


def test_play_searches_by_turning_when_the_ball_is_out_of_view():
    clock, world, dog = make_dog(ball=HIDDEN_BALL, look_rate=0.5)
    clock.tickers.append(lambda t, dt: setattr(clock, 'shut', t >= 2.0))
    Play(dog).execute(None)
    assert world.yaw != pytest.approx(math.pi), 'it turned in place, searching'


def test_whole_machine_normal_play_normal_sleep_normal():
    clock, world, dog = make_dog(seed=3, sleep_probability=0.0)
    states = []
    sm = build_state_machine(dog)
    report_active_state(sm, lambda label: states.append((clock.now(), label)))

    def script(t, dt):
        if t >= 20.0 and world.ball_visible:
            world.ball_visible = False        # PLAY -> lost -> NORMAL
        if states and states[-1][1] == 'NORMAL' and len(states) == 3:
            dog.p.sleep_probability = 1.0     # the next round sleeps
        if len(states) >= 5:
            clock.shut = True
    clock.tickers.append(script)
    assert sm.execute() == 'shutdown'
    labels = [label for _, label in states]
    assert labels[:5] == ['NORMAL', 'PLAY', 'NORMAL', 'SLEEP', 'NORMAL']


@pytest.mark.parametrize('bad', [-1.0, float('nan'), float('inf')])
def test_params_refuse_negative_or_non_finite_numbers(bad):
    with pytest.raises(ValueError, match='sleep_time'):
        DogParams(lambda k, d: bad if k == 'sleep_time' else d)


def test_lost_timeout_defaults_to_one_full_search_turn():
    assert DogParams(lambda k, d: 0.25 if k == 'look_rate' else d).lost_timeout == \
        pytest.approx(8 * math.pi)

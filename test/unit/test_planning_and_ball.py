"""Goal checks, the servers' control steps, the ball's routine and a person's
ball commands (no ROS)."""
import math
import random

import pytest

from exp_assignment2 import arena
from exp_assignment2.behaviour.ball import HIDE_Z, BallCommands, BallRoutine
from exp_assignment2.control import GoToPoint
from exp_assignment2.planning import (ANGLE_ALIGNED, FIXING_YAW, REACHED, REACHING,
                                      BallGoalController, RobotGoalController, goal_error)

from fakes import FakeClock, FakeGoal, RecordingLog

NAN, INF = float('nan'), float('inf')


@pytest.mark.parametrize('x,y,z', [(0, 0, None), (8, -8, None), (1, 1, 0.5), (1, 1, -1.0),
                                   (1, 1, 20.0), (1, 1, 50.0)])
def test_goals_inside_the_arena_are_accepted(x, y, z):
    assert goal_error(x, y, z) is None


@pytest.mark.parametrize('x,y,z,why', [
    (8.01, 0, None, 'outside the arena'), (0, -9, None, 'outside the arena'),
    (NAN, 0, None, 'not finite'), (0, INF, None, 'not finite'),
    (1, 1, NAN, 'not finite'), (1, 1, 50.5, 'may rise to'), ('a', 1, None, 'not numeric')])
def test_bad_goals_are_refused_with_the_reason(x, y, z, why):
    assert why in goal_error(x, y, z)


@pytest.mark.parametrize('x,y,z,text', [
    (1e308, 0.0, None, 'goal x, y = (1e+308, 0) is outside the arena'),
    (-0.0, -INF, None, 'goal x, y = (-0, -inf) is not finite'),
    (-0.0, -1e15, None, 'goal x, y = (-0, -1e+15) is outside the arena'),
    (1.0, 2.5, 1e15, 'goal z = 1e+15 is above'),
    (1.0, 2.5, -NAN, 'goal z = nan (the ball\'s height) is not finite')])
def test_refusals_print_every_number_one_way(x, y, z, text):
    assert goal_error(x, y, z).startswith(text)
    assert len(goal_error(x, y, z)) < 120


def test_z_is_not_checked_where_it_is_ignored():
    assert goal_error(1.0, 1.0) is None          # the robot server passes no z


def drive(controller, x, y, yaw, gx, gy, dt=0.02):
    """Integrate a unicycle under the robot controller; the feedback texts in order."""
    texts = []
    controller.begin()
    for _ in range(5000):
        (v, w), said, done = controller.step(x, y, yaw, gx, gy)
        texts.extend(t for t in said if not texts or texts[-1] != t)
        if done:
            return (x, y), texts
        yaw += w * dt
        x += v * math.cos(yaw) * dt
        y += v * math.sin(yaw) * dt
    raise AssertionError('never arrived')


def test_the_robot_controller_speaks_the_original_wording_in_order():
    (x, y), texts = drive(RobotGoalController(GoToPoint()), -5.0, 7.0, math.pi, 0.0, 0.0)
    assert math.hypot(x, y) <= 0.1
    assert texts == [FIXING_YAW, ANGLE_ALIGNED, REACHING, REACHED]


def test_the_ball_controller_goes_straight_at_capped_speed():
    ctrl = BallGoalController(kp=0.5, max_speed=2.0, precision=0.1)
    (vx, vy), texts, done = ctrl.step(-7.0, 6.0, 7.0, 6.0)
    assert (vx, vy) == (pytest.approx(2.0), 0.0) and texts == [REACHING] and not done
    assert ctrl.step(7.0, 6.05, 7.0, 6.0) == ((0.0, 0.0), [REACHED], True)


class FakeBall(object):
    """Ball goals that finish after ``travel`` s of the fake clock."""

    def __init__(self, clock, travel=3.0):
        self.clock, self.travel, self.goals = clock, travel, []
        clock.tickers.append(self.tick)

    def go_to(self, x, y, z):
        goal = FakeGoal(self, x, y)
        goal.z, goal.sent = z, self.clock.now()
        self.goals.append(goal)
        return goal

    def tick(self, now, dt):
        for goal in self.goals:
            if not goal.done() and now - goal.sent >= self.travel:
                goal.state = 'succeeded'


def test_the_routine_moves_waits_and_disappears_in_the_original_rhythm():
    clock = FakeClock()
    ball = FakeBall(clock)
    routine = BallRoutine(clock, ball, random.Random(1), RecordingLog(), wait_time=8.0,
                          hidden_time=10.0, moves_per_round=2)
    routine.round()
    assert [g.z for g in ball.goals] == [arena.BALL_GROUND_Z, arena.BALL_GROUND_Z, HIDE_Z]
    assert [g.sent for g in ball.goals] == pytest.approx([0.0, 11.0, 22.0], abs=0.11)
    assert clock.now() == pytest.approx(22.0 + 3.0 + 10.0, abs=0.2)
    assert all(arena.in_arena(*g.target) for g in ball.goals)


def test_pausing_the_routine_cancels_its_goal_and_resuming_starts_a_round():
    clock = FakeClock()
    ball = FakeBall(clock, travel=100.0)
    routine = BallRoutine(clock, ball, random.Random(1), RecordingLog())
    clock.tickers.append(lambda t, dt: routine.set_enabled(False) if t >= 1.0 else None)
    routine.round()
    assert ball.goals[0].state == 'cancelled' and len(ball.goals) == 1
    assert 'paused' in routine.log.text()


def make_commands(position=(1.0, 2.0)):
    clock = FakeClock()
    ball, auto, refused = FakeBall(clock), [], []
    commands = BallCommands(ball, auto.append, lambda: position, refused.append,
                            RecordingLog())
    return commands, ball, auto, refused


def test_go_to_moves_the_ball_on_the_ground_and_pauses_the_routine():
    commands, ball, auto, _ = make_commands()
    assert commands.handle('go to -2 -3') == 'go_to'
    assert ball.goals[0].target == (-2.0, -3.0) and ball.goals[0].z == arena.BALL_GROUND_Z
    assert auto == [False]


def test_hide_and_show_change_the_height_where_the_ball_is():
    commands, ball, _, _ = make_commands(position=(9.5, -2.0))
    commands.handle('hide')
    commands.handle('show')
    assert [(g.target, g.z) for g in ball.goals] == [((8.0, -2.0), HIDE_Z),
                                                      ((8.0, -2.0), arena.BALL_GROUND_Z)]


def test_auto_resumes_and_stop_cancels_the_person_s_goal():
    commands, ball, auto, _ = make_commands()
    commands.handle('go to 1 1')
    commands.handle('stop')
    commands.handle('auto')
    assert ball.goals[0].state == 'cancelled' and auto == [False, False, True]


def test_a_bad_command_is_refused_and_changes_nothing():
    commands, ball, auto, refused = make_commands()
    assert commands.handle('go to 100 0') is None
    assert ball.goals == [] and auto == [] and 'outside the arena' in refused[0]


def test_hide_before_the_ball_position_is_known_is_refused():
    commands, ball, auto, refused = make_commands(position=None)
    assert commands.handle('hide') is None
    assert ball.goals == [] and 'not known yet' in refused[0]


def test_the_routine_stops_quietly_when_ros_shuts_down():
    clock = FakeClock()
    ball = FakeBall(clock)
    routine = BallRoutine(clock, ball, random.Random(1), RecordingLog())
    clock.tickers.append(lambda t, dt: setattr(clock, 'shut', t >= 1.0))
    routine.round()
    assert len(ball.goals) == 1, 'no new goal once shut down'
    assert routine.log.lines == [('info', 'move_ball_around: ball to (%.1f, %.1f)'
                                  % ball.goals[0].target)]

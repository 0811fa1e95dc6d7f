"""Control laws on poses: turning direction, phases, stopping distance."""
import math

import pytest

from exp_assignment2.control import (DONE, FIX_YAW, GO_STRAIGHT, BallFollower, GoToPoint,
                                     planar_velocity, visual_servo)
from exp_assignment2.geometry import normalize_angle, world_to_body


def simulate(ctrl, x, y, yaw, gx, gy, dt=0.02, steps=5000):
    """Integrate a unicycle under the controller; return the final pose and phases."""
    phases = []
    for _ in range(steps):
        cmd, phase = ctrl.update(x, y, yaw, gx, gy)
        phases.append(phase)
        if phase == DONE:
            break
        yaw += cmd.angular * dt
        x += cmd.linear * math.cos(yaw) * dt
        y += cmd.linear * math.sin(yaw) * dt
    return x, y, yaw, phases


def test_normalize_angle():
    assert normalize_angle(3 * math.pi / 2) == pytest.approx(-math.pi / 2)
    assert normalize_angle(-3 * math.pi / 2) == pytest.approx(math.pi / 2)
    assert normalize_angle(0.3) == pytest.approx(0.3)


def test_goal_to_the_left_turns_left_first():
    cmd, phase = GoToPoint().update(0, 0, 0, 0, 5)
    assert phase == FIX_YAW and cmd.linear == 0 and cmd.angular > 0


def test_goal_to_the_right_turns_right_first():
    cmd, phase = GoToPoint().update(0, 0, 0, 0, -5)
    assert phase == FIX_YAW and cmd.angular < 0


def test_goal_ahead_drives_straight():
    cmd, phase = GoToPoint().update(0, 0, 0, 5, 0)
    assert phase == GO_STRAIGHT and cmd.linear > 0 and abs(cmd.angular) < 1e-9


@pytest.mark.parametrize('goal', [(5, 5), (-7, 2), (0, -8), (8, -8)])
def test_reaches_goal_within_precision(goal):
    ctrl = GoToPoint()
    x, y, _, phases = simulate(ctrl, 0.0, 0.0, 1.0, *goal)
    assert phases[-1] == DONE
    assert math.hypot(goal[0] - x, goal[1] - y) <= ctrl.dist_precision + 1e-9
    assert phases[0] == FIX_YAW and GO_STRAIGHT in phases


def test_speeds_are_capped():
    cmd, _ = GoToPoint().update(0, 0, 0, 100, 0)
    assert cmd.linear <= 0.6
    cmd, _ = GoToPoint().update(0, 0, 0, -100, 1)
    assert abs(cmd.angular) <= 0.6


def test_planar_velocity_points_at_goal_and_is_capped():
    vx, vy = planar_velocity(0, 0, 3, 4, kp=0.5, max_speed=2.0)
    assert math.hypot(vx, vy) == pytest.approx(2.0)
    assert vy / vx == pytest.approx(4 / 3)
    assert planar_velocity(1, 1, 1, 1) == (0, 0)


def test_visual_servo_turns_towards_the_ball():
    right = visual_servo(ball_x=300, ball_radius=40, width=320)
    left = visual_servo(ball_x=20, ball_radius=40, width=320)
    assert right.angular < 0 < left.angular


def test_visual_servo_drives_to_target_size_and_stops_there():
    far = visual_servo(160, 20, 320, target_radius_ratio=0.25)
    near = visual_servo(160, 120, 320, target_radius_ratio=0.25)
    there = visual_servo(160, 80, 320, target_radius_ratio=0.25)
    assert far.linear > 0 > near.linear
    assert there.linear == pytest.approx(0) and there.angular == pytest.approx(0)


def test_visual_servo_matches_the_original_gains_at_800px():
    # original: angular = 0.002 * (cx - 400), linear = -0.01 * (r - 100), at 800 px
    cmd = visual_servo(450, 90, 800, target_radius_ratio=100 / 800.0,
                       max_angular=10, max_linear=10)
    assert cmd.angular == pytest.approx(-0.002 * 50)    # REP 103 sign
    assert cmd.linear == pytest.approx(-0.01 * (90 - 100))


def test_ball_follower_searches_when_no_ball_and_servoes_otherwise():
    from exp_assignment2.vision import Ball
    follower = BallFollower(target_radius_ratio=0.3, search_rate=0.5)
    assert follower.command(None, 800) == (0.0, 0.5)
    right = follower.command(Ball(600, 400, 50, 600, 400), 800)
    assert right.angular < 0 and right.linear > 0     # ball right and far: turn right, go
    at_target = follower.command(Ball(400, 400, 240, 400, 400), 800)
    assert at_target == (pytest.approx(0.0), pytest.approx(0.0))


@pytest.mark.parametrize('yaw', [0.0, math.radians(159), -2.0, math.pi, 7.0])
def test_a_world_velocity_in_the_body_frame_moves_the_body_along_it(yaw):
    vx, vy = 0.6, -0.8
    bx, by = world_to_body(vx, vy, yaw)
    # what planar_move does with a body-frame command: rotate it by the heading
    wx = bx * math.cos(yaw) - by * math.sin(yaw)
    wy = bx * math.sin(yaw) + by * math.cos(yaw)
    assert abs(wx - vx) < 1e-12 and abs(wy - vy) < 1e-12

"""The engine's own stepping code on real pybullet physics (no ROS): the
drive plugins the URDFs' <gazebo> tags name (their ROS-free cores, under the
same file names), limits, timeouts, the head, the ball's height, bounds, the
guard and resets."""
import math

import pytest

from exp_assignment2.geometry import yaw_of
from exp_assignment2.sim.drives import JointPosition
from exp_assignment2.sim.model import HIDDEN_Z
from exp_assignment2.sim.offline import make_engine
from exp_assignment2.sim.plugins.cores import CORES


class Sim(object):
    """An engine with the cores of the drive plugins, driven by hand."""

    def __init__(self, world='world_dog.yaml', robot='rep103', cmd_timeout=0.5, **kw):
        self.engine = make_engine(world, robot, registry=CORES,
                                  settings=dict(cmd_timeout=cmd_timeout), **kw)
        self.drives = {name: plugins[0] for name, plugins in self.engine.plugins.items()
                       if plugins}
        self.head = (JointPosition(self.engine.models['robot'], 'head_joint')
                     if 'robot' in self.engine.models else None)
        if self.head is not None:
            self.engine.step_listeners.append(lambda engine: self.head.apply())

    def command(self, name):
        return self.drives[name].command

    def run(self, seconds, name=None, command=None):
        """Step ``seconds``, repeating ``command`` (vx, vy, wz) on ``name`` at 20 Hz."""
        for i in range(int(round(seconds / self.engine.time_step))):
            if command is not None and i % 5 == 0:
                self.command(name).command(*command)
            self.engine.step()

    def pose(self, name):
        (x, y, z), quat = self.engine.models[name].pose()
        return x, y, z, yaw_of(quat)

    def close(self):
        self.engine.close()


@pytest.fixture
def dog():
    sim = Sim()
    yield sim
    sim.close()


def turned(before, after):
    return math.atan2(math.sin(after - before), math.cos(after - before))


def test_the_models_bring_their_plugins_from_their_gazebo_tags(dog):
    assert sorted(dog.drives) == ['ball', 'robot']
    assert type(dog.drives['robot']).__name__ == 'DiffDriveCore'
    assert type(dog.drives['ball']).__name__ == 'PlanarMoveCore'
    assert dog.engine.models['ball'].kinematic and dog.engine.models['arena'].static


def test_the_robot_spawns_where_the_world_says(dog):
    x, y, z, yaw = dog.pose('robot')
    assert (x, y) == (pytest.approx(-5.0, abs=1e-3), pytest.approx(7.0, abs=1e-3))
    assert abs(turned(yaw, math.pi)) < 1e-3


@pytest.mark.parametrize('robot,sign', [('rep103', 1), ('original', -1)])
def test_positive_angular_z_turns_left_on_rep103_and_right_on_the_original(robot, sign):
    """The original sets legacyMode true, which Noetic's diff drive does not read:
    its leftJoint, on the robot's right, turns at v - w s/2."""
    sim = Sim(robot=robot)
    try:
        assert sim.drives['robot'].drive.turn_sign() == sign
        yaw0 = sim.pose('robot')[3]
        sim.run(1.0, 'robot', (0.0, 0.0, 0.5))
        assert sign * turned(yaw0, sim.pose('robot')[3]) > 0.2
    finally:
        sim.close()


def test_forward_follows_the_heading(dog):
    x0, y0, _, yaw = dog.pose('robot')
    dog.run(2.0, 'robot', (0.4, 0.0, 0.0))
    x1, y1, _, _ = dog.pose('robot')
    along = (x1 - x0) * math.cos(yaw) + (y1 - y0) * math.sin(yaw)
    across = -(x1 - x0) * math.sin(yaw) + (y1 - y0) * math.cos(yaw)
    assert along > 0.5 and abs(across) < 0.05


def test_a_stale_command_stops_the_body(dog):
    dog.command('robot').command(0.5, 0.0, 0.0)
    dog.run(1.5)                        # one command, then silence: 0.5 s timeout
    x0, y0, _, _ = dog.pose('robot')
    dog.run(1.0)
    x1, y1, _, _ = dog.pose('robot')
    assert math.hypot(x1 - x0, y1 - y0) < 0.01


def test_cmd_timeout_zero_keeps_the_last_command_as_gazebo_did():
    sim = Sim(cmd_timeout=0.0)
    try:
        sim.command('robot').command(0.5, 0.0, 0.0)
        sim.run(1.5)
        x0, y0, _, _ = sim.pose('robot')
        sim.run(1.0)
        x1, y1, _, _ = sim.pose('robot')
        assert math.hypot(x1 - x0, y1 - y0) > 0.3
    finally:
        sim.close()


@pytest.mark.parametrize('bad', [float('nan'), float('inf'), -float('inf')])
def test_a_non_finite_command_is_refused(dog, bad):
    with pytest.raises(ValueError, match='not finite'):
        dog.command('robot').command(bad, 0.0, 0.0)
    assert dog.command('robot').current() == (0.0, 0.0, 0.0)


def test_a_huge_command_is_clamped_and_reported(dog):
    command = dog.command('robot')
    assert command.command(1.0e308, 0.0, -1.0e308) is True
    assert command.current() == (pytest.approx(2.0), 0.0, -3.0)
    assert command.command(1.0, 0.0, 1.0) is False
    x0, y0, _, _ = dog.pose('robot')
    dog.run(1.0, 'robot', (1.0e308, 0.0, 0.0))
    x1, y1, z1, _ = dog.pose('robot')
    assert all(math.isfinite(v) for v in (x1, y1, z1))
    assert math.hypot(x1 - x0, y1 - y0) < 2.0 * 1.05


def test_the_head_follows_its_command_and_is_clamped(dog):
    assert dog.head.command(0.6) == 0.6
    dog.run(1.5)
    names, positions, _, _ = dog.engine.models['robot'].joint_states()
    assert positions[names.index('head_joint')] == pytest.approx(0.6, abs=0.02)
    assert dog.head.command(3.0) == pytest.approx(math.pi / 2, abs=1e-3)
    with pytest.raises(ValueError):
        dog.head.command(float('nan'))


def test_the_ball_s_height_hides_it_under_the_ground_and_brings_it_back(dog):
    ball = dog.engine.models['ball']
    x, y, _, _ = dog.pose('ball')
    ball.set_pose((x, y, -1.0))
    assert ball.hidden and dog.pose('ball')[2] == -1.0
    assert ball.link_pose('ball_link')[0][2] == -1.0
    ball.set_pose((x, y, 20.0))
    assert not ball.hidden and dog.pose('ball')[2] == 20.0
    ball.set_pose((x, y, 0.5))
    assert dog.pose('ball')[2] == 0.5 and not ball.hidden


def test_the_ball_cannot_leave_the_arena_however_it_is_pushed(dog):
    dog.run(30.0, 'ball', (1.0e308, -1.0e308, 0.0))
    x, y, _, _ = dog.pose('ball')
    assert (x, y) == (pytest.approx(8.8), pytest.approx(-8.8))


def test_planar_move_commands_are_in_the_body_frame():
    """Gazebo's planar_move: x forward of the body, whatever its heading."""
    sim = Sim(world='world_miro.yaml')
    try:
        sim.run(1.0, 'miro', (0.0, 0.0, math.pi / 2))
        x0, y0, _, yaw = sim.pose('miro')
        sim.run(1.0, 'miro', (0.5, 0.0, 0.0))
        x1, y1, _, _ = sim.pose('miro')
        assert yaw == pytest.approx(math.pi / 2, abs=0.1)
        assert (x1 - x0, y1 - y0) == (pytest.approx(0.0, abs=0.08), pytest.approx(0.5, abs=0.08))
    finally:
        sim.close()


def test_miro_stays_on_its_grid_and_finite_under_a_huge_command():
    sim = Sim(world='world_miro.yaml')
    try:
        sim.run(20.0, 'miro', (1.0e308, 1.0e308, 0.0))
        x, y, z, _ = sim.pose('miro')
        assert all(math.isfinite(v) for v in (x, y, z))
        assert -0.25 <= x <= 10.25 and -0.25 <= y <= 10.25 and abs(z) < 0.2
    finally:
        sim.close()


def test_the_guard_puts_a_non_finite_body_back_and_reset_restores_every_body(dog):
    from exp_assignment2.sim.bullet import p
    dog.run(2.0, 'robot', (1.0e308, 0.0, 1.0e308))
    dog.run(2.0, 'ball', (1.0e308, 0.0, 0.0))
    robot = dog.engine.models['robot']
    p.resetBasePositionAndOrientation(robot.id, [float('nan')] * 3, [0, 0, 0, 1],
                                      physicsClientId=robot.client)
    region = dog.engine._guard_region
    assert robot.trouble(region) == 'had a non-finite pose'
    dog.engine.step()                   # the guard
    assert robot.trouble(region) is None
    assert dog.pose('robot')[:2] == (pytest.approx(-5.0, abs=1e-2), pytest.approx(7.0, abs=1e-2))
    dog.engine.reset_world()
    assert dog.pose('ball')[:3] == (-7.0, 6.0, 0.5)


def test_a_body_that_left_the_world_is_put_back_and_drives_again(dog):
    robot = dog.engine.models['robot']
    for outside in ((40.0, 0.0, 0.1), (0.0, 0.0, -12.0)):       # beyond the walls, under the floor
        robot.set_pose(outside, (0.0, 0.0, 0.0, 1.0))
        dog.engine.step()
        assert dog.pose('robot')[:2] == (pytest.approx(-5.0, abs=1e-2),
                                         pytest.approx(7.0, abs=1e-2))
    dog.run(2.0, 'robot', (0.5, 0.0, 0.0))                      # on the floor, and it drives
    x, y, z, _ = dog.pose('robot')
    assert 0.05 < z < 0.2 and math.hypot(x + 5.0, y - 7.0) > 0.5


def test_reset_simulation_sets_the_time_back_and_the_plugins_count_from_there(dog):
    dog.run(1.0, 'robot', (0.5, 0.0, 0.0))
    assert dog.engine.time == pytest.approx(1.0)
    dog.engine.reset_simulation()
    assert dog.engine.time == 0.0 and dog.engine.time_ns == 0
    assert dog.command('robot').current() == (0.0, 0.0, 0.0)
    dog.run(0.5, 'robot', (0.5, 0.0, 0.0))
    assert dog.engine.time == pytest.approx(0.5)


def test_a_kinematic_body_can_start_hidden_and_reset_keeps_that():
    sim = Sim(hidden=('ball',))
    try:
        ball = sim.engine.models['ball']
        assert ball.hidden
        ball.set_pose((-7.0, 6.0, 0.5))
        assert not ball.hidden
        sim.engine.reset_world()
        from exp_assignment2.sim.bullet import p
        assert ball.hidden and p.getBasePositionAndOrientation(
            ball.id, physicsClientId=ball.client)[0][2] == HIDDEN_Z
    finally:
        sim.close()

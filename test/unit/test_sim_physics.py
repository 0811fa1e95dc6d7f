"""The simulator's ROS-free parts on real pybullet physics: drives, limits,
timeouts, the head, the ball's height, bounds and reset (no ROS)."""
import math

import pytest

from exp_assignment2.geometry import yaw_of
from exp_assignment2.sim.drives import DiffDrive, Height, JointPosition, PlanarMove
from exp_assignment2.sim.offline import load_world, make_physics
from exp_assignment2.sim.physics import HIDDEN_Z

class Sim(object):
    """Physics plus the drives the world asks for, stepped by hand."""

    def __init__(self, world='world_dog.yaml', robot='rep103', cmd_timeout=None):
        self.world = load_world(world)
        if cmd_timeout is not None:
            for model in self.world.models:
                for name in ('diff_drive', 'planar_move'):
                    if name in model.plugins:
                        model.plugins[name]['cmd_timeout'] = cmd_timeout
        self.physics = make_physics(self.world, robot)
        self.drives = {}
        for model in self.world.models:
            opts = model.plugins
            if 'diff_drive' in opts:
                self.drives[model.name] = DiffDrive(self.physics, model.name, opts['diff_drive'])
            if 'planar_move' in opts:
                self.drives[model.name] = PlanarMove(self.physics, model.name,
                                                     opts['planar_move'], self.world.bounds)
            if 'joint_position' in opts:
                self.head = JointPosition(self.physics, model.name, opts['joint_position'])
            if 'height' in opts:
                self.height = Height(self.physics, model.name, opts['height'])
        self.controllers = list(self.drives.values()) + [
            c for c in (getattr(self, 'head', None),) if c is not None]

    def run(self, seconds, name=None, command=None):
        """Step ``seconds``, repeating ``command`` (vx, vy, wz) on ``name`` at 20 Hz."""
        for i in range(int(round(seconds / self.physics.time_step))):
            if command is not None and i % 5 == 0:
                self.drives[name].command(*command)
            for controller in self.controllers:
                controller.apply()
            self.physics.step()

    def pose(self, name):
        (x, y, z), quat = self.physics.base_pose(name)
        return x, y, z, yaw_of(quat)

    def close(self):
        self.physics.close()


@pytest.fixture
def dog():
    sim = Sim()
    yield sim
    sim.close()


def turned(before, after):
    return math.atan2(math.sin(after - before), math.cos(after - before))


def test_the_robot_spawns_where_the_world_says(dog):
    x, y, z, yaw = dog.pose('robot')
    assert (x, y) == (pytest.approx(-5.0, abs=1e-3), pytest.approx(7.0, abs=1e-3))
    assert abs(turned(yaw, math.pi)) < 1e-3


@pytest.mark.parametrize('robot,sign', [('rep103', 1), ('original', -1)])
def test_positive_angular_z_turns_left_on_rep103_and_right_on_the_original(robot, sign):
    sim = Sim(robot=robot)
    try:
        assert sim.drives['robot'].turn_sign == sign
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
    dog.drives['robot'].command(0.5, 0.0, 0.0)
    dog.run(1.5)                        # one command, then silence: 0.5 s timeout
    x0, y0, _, _ = dog.pose('robot')
    dog.run(1.0)
    x1, y1, _, _ = dog.pose('robot')
    assert math.hypot(x1 - x0, y1 - y0) < 0.01


def test_cmd_timeout_zero_keeps_the_last_command_as_gazebo_did():
    sim = Sim(cmd_timeout=0.0)
    try:
        sim.drives['robot'].command(0.5, 0.0, 0.0)
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
        dog.drives['robot'].command(bad, 0.0, 0.0)
    assert dog.drives['robot'].current() == (0.0, 0.0, 0.0)


def test_a_huge_command_is_clamped_and_reported(dog):
    drive = dog.drives['robot']
    assert drive.command(1.0e308, 0.0, -1.0e308) is True
    assert drive.current() == (pytest.approx(2.0), 0.0, -3.0)
    assert drive.command(1.0, 0.0, 1.0) is False
    x0, y0, _, _ = dog.pose('robot')
    dog.run(1.0, 'robot', (1.0e308, 0.0, 0.0))
    x1, y1, z1, _ = dog.pose('robot')
    assert all(math.isfinite(v) for v in (x1, y1, z1))
    assert math.hypot(x1 - x0, y1 - y0) < 2.0 * 1.05


def test_the_head_follows_its_command_and_is_clamped(dog):
    assert dog.head.command(0.6) == 0.6
    dog.run(1.5)
    names, positions, _, _ = dog.physics.joint_states('robot')
    assert positions[names.index('head_joint')] == pytest.approx(0.6, abs=0.02)
    assert dog.head.command(3.0) == pytest.approx(math.pi / 2, abs=1e-3)
    with pytest.raises(ValueError):
        dog.head.command(float('nan'))


def test_the_ball_s_height_hides_it_under_the_ground_and_brings_it_back(dog):
    assert dog.height.command(-1.0) == -1.0
    body = dog.physics.bodies['ball']
    assert body.hidden and dog.pose('ball')[2] == -1.0
    assert dog.physics.link_pose('ball', 'ball_link')[0][2] == -1.0
    assert dog.height.command(20.0) == 20.0 and not body.hidden
    assert dog.height.command(1000.0) == 50.0
    dog.height.command(0.5)
    assert dog.pose('ball')[2] == 0.5 and not body.hidden


def test_the_ball_cannot_leave_the_arena_however_it_is_pushed(dog):
    dog.run(30.0, 'ball', (1.0e308, -1.0e308, 0.0))
    x, y, _, _ = dog.pose('ball')
    assert (x, y) == (pytest.approx(8.8), pytest.approx(-8.8))


def test_miro_stays_on_its_grid_and_finite_under_a_huge_command():
    sim = Sim(world='world_miro.yaml')
    try:
        sim.run(20.0, 'miro', (1.0e308, 1.0e308, 0.0))
        x, y, z, _ = sim.pose('miro')
        assert all(math.isfinite(v) for v in (x, y, z))
        assert -0.25 <= x <= 10.25 and -0.25 <= y <= 10.25 and abs(z) < 0.2
    finally:
        sim.close()


def test_reset_restores_every_body_even_after_abuse(dog):
    from exp_assignment2.sim.bullet import p
    dog.run(2.0, 'robot', (1.0e308, 0.0, 1.0e308))
    dog.run(2.0, 'ball', (1.0e308, 0.0, 0.0))
    robot = dog.physics.bodies['robot'].id
    p.resetBasePositionAndOrientation(robot, [float('nan')] * 3, [0, 0, 0, 1],
                                      physicsClientId=dog.physics.client)
    assert not dog.physics.finite('robot')
    for name in dog.physics.bodies:
        dog.physics.reset_body(name)
    assert dog.physics.finite('robot')
    assert dog.pose('robot')[:2] == (pytest.approx(-5.0, abs=1e-3), pytest.approx(7.0, abs=1e-3))
    assert dog.pose('ball')[:3] == (-7.0, 6.0, 0.5)


def test_a_kinematic_body_can_start_hidden_and_reset_keeps_that(dog):
    body = dog.physics.bodies['ball']
    body.hidden = body.spawn_hidden = True
    dog.height.command(0.5)
    dog.physics.reset_body('ball')
    assert body.hidden
    from exp_assignment2.sim.bullet import p
    assert p.getBasePositionAndOrientation(body.id, physicsClientId=dog.physics.client)[0][2] \
        == HIDDEN_Z

"""The ROS release the simulator follows (sim.releases): Kinetic's diff drive
honours legacyMode and swaps the wheels, Melodic's and Noetic's do not read
it; encoder odometry, frames and gazebo_ros_control's legacyModeNS per
release; an unknown release refused. The engine alone, no master."""
import math
import os

import pytest

from exp_assignment2.geometry import yaw_of
from exp_assignment2.sim import releases, urdf
from exp_assignment2.sim.drives import EncoderOdometry, diff_drive_turn_sign
from exp_assignment2.sim.engine import Engine
from exp_assignment2.sim.offline import URDF_DIR, make_engine
from exp_assignment2.sim.plugins.cores import CORES
from exp_assignment2.sim.world import parse_world
from fakes import RecordingLog

LEGACY = '<legacyMode>true</legacyMode>'


def course_robot(legacy=LEGACY, odometry='world'):
    """The course robot's URDF (joint_left_wheel on its right, legacyMode
    true), with its legacyMode tag replaced by ``legacy`` ('' : none) and
    its odometrySource ``odometry``."""
    with open(os.path.join(URDF_DIR, 'robot_original.urdf')) as f:
        text = f.read()
    source = '<odometrySource>world</odometrySource>'
    assert LEGACY in text and source in text
    return text.replace(LEGACY, legacy).replace(
        source, '<odometrySource>%s</odometrySource>' % odometry)


class World(object):
    """The arena and the course robot, driven through the diff drive's core
    as the release named runs it."""

    def __init__(self, release, robot_urdf):
        arena = parse_world({'bounds': [-8.8, 8.8, -8.8, 8.8],
                             'models': [{'name': 'arena', 'urdf': 'arena.urdf', 'grid': True}]})
        self.log = RecordingLog()
        self.engine = make_engine(arena, registry=CORES, log=self.log,
                                  settings=dict(ros_release=release, cmd_timeout=0.5))
        self.engine.spawn('robot', robot_urdf, (0.0, 0.0, 0.1, 0.0), 'robot', base_dir=URDF_DIR)
        self.drive = self.engine.plugins['robot'][0]

    def yaw(self):
        return yaw_of(self.engine.models['robot'].pose()[1])

    def run(self, seconds, command):
        for i in range(int(round(seconds / self.engine.time_step))):
            if i % 5 == 0:
                self.drive.command.command(*command)
            self.engine.step()

    def close(self):
        self.engine.close()


def turned_by(release, robot_urdf, command=(0.0, 0.0, 0.5), seconds=1.0):
    world = World(release, robot_urdf)
    try:
        yaw0 = world.yaw()
        world.run(seconds, command)
        return math.atan2(math.sin(world.yaw() - yaw0), math.cos(world.yaw() - yaw0))
    finally:
        world.close()


@pytest.mark.parametrize('release,direction', [('kinetic', 1), ('melodic', -1), ('noetic', -1)])
def test_legacy_mode_turns_the_course_robot_left_on_kinetic_only(release, direction):
    """+angular.z with legacyMode true: Kinetic swaps the wheels (the course
    robot's leftJoint is on its right), so it turns left; Melodic and Noetic
    do not read the tag and it turns right."""
    assert direction * turned_by(release, course_robot()) > 0.2


@pytest.mark.parametrize('legacy,kinetic_sign,said', [
    ('', 1, ('error', 'missing <legacyMode>')), ('<legacyMode>false</legacyMode>', -1, None),
    ('<legacyMode>FALSE</legacyMode>', -1, None),
    ('<legacyMode>0</legacyMode>', 1, ('warn', "<legacyMode> '0' is not true or false"))])
def test_kinetic_s_default_is_legacy_and_the_others_ignore_the_tag(legacy, kinetic_sign, said):
    """Kinetic's plugin reads legacyMode with default true (gazebo_ros_diff_drive.cpp
    2.5.x: getParameterBoolean(legacy_mode_, "legacyMode", true), which takes
    only true or false, any case): without the tag, or with 0, it swaps too,
    and says so. Melodic and Noetic: the same whatever the tag."""
    text = course_robot(legacy)
    parsed = urdf.parse(text)
    assert diff_drive_turn_sign(parsed, releases.release('kinetic')) == kinetic_sign
    for other in ('melodic', 'noetic'):
        assert diff_drive_turn_sign(parsed, releases.release(other)) == -1
    world = World('kinetic', text)
    try:
        assert world.drive.drive.turn_sign() == kinetic_sign
        assert world.drive.facts()['legacy_mode'] == (kinetic_sign == 1)
        lines = [(level, t) for level, t in world.log.lines if 'legacyMode' in t]
        assert len(lines) == (0 if said is None else 1)
        if said is not None:
            assert lines[0][0] == said[0] and said[1] in lines[0][1]
    finally:
        world.close()
    if not legacy:       # the physics agrees with the sign
        assert turned_by('kinetic', text) > 0.2


def test_the_package_robot_turns_left_in_every_release():
    """urdf/robot.urdf says legacyMode false: no release swaps it."""
    with open(os.path.join(URDF_DIR, 'robot.urdf')) as f:
        parsed = urdf.parse(f.read())
    assert {diff_drive_turn_sign(parsed, r) for r in releases.RELEASES.values()} == {1}


@pytest.mark.parametrize('release', ['kinetic', 'noetic'])
def test_encoder_odometry_follows_each_release(release):
    """odometrySource encoder on the course robot turning left or right:
    Kinetic's legacy odometry turns the way the robot does and its twist is
    the odometry frame's dx/dt, dy/dt; Noetic's turns by (right - left) of the
    joints named so, the mirror of the course robot's real turn, and its twist
    is the forward speed in the child frame (linear.y 0)."""
    world = World(release, course_robot(odometry='encoder'))
    try:
        yaw0 = world.yaw()
        world.run(1.5, (0.3, 0.0, 0.6))
        real = world.yaw() - yaw0
        encoder = world.drive.encoder
        vx, vy, wz = encoder.twist
        assert abs(real) > 0.2
        if release == 'kinetic':
            assert real * encoder.pose[2] > 0 and real * wz > 0
            theta = encoder.pose[2]           # the odometry frame's velocity, at its heading
            assert vy == pytest.approx(math.tan(theta) * vx, rel=0.1) and abs(vy) > 0.02
        else:
            assert real * encoder.pose[2] < 0 and real * wz < 0
            assert vy == 0.0 and vx == pytest.approx(0.3, rel=0.25)
    finally:
        world.close()


def test_encoder_odometry_alone():
    """The dead reckoning itself: straight ahead, then a legacy turn."""
    straight = EncoderOdometry(radius=0.1, separation=0.2)
    for _ in range(100):
        straight.step(2.0, 2.0, 0.01)                  # 0.2 m/s for 1 s
    assert straight.pose == pytest.approx([0.2, 0.0, 0.0])
    assert straight.twist == pytest.approx((0.2, 0.0, 0.0))
    for swapped, sign in ((False, 1), (True, -1)):
        odometry = EncoderOdometry(0.1, 0.2, swapped=swapped, twist_in_child_frame=False)
        odometry.step(1.0, 3.0, 0.1)                   # the right joint faster
        assert sign * odometry.pose[2] == pytest.approx(0.1)
        assert odometry.twist[:2] == pytest.approx((odometry.pose[0] / 0.1,
                                                    odometry.pose[1] / 0.1))


def test_frames_are_prefixed_with_the_namespace_before_noetic():
    """tf::resolve with the robot namespace as tf_prefix (Kinetic, Melodic),
    none since Noetic 2.9.2 (#1143, #1173); an absolute frame loses its slash."""
    kinetic, melodic, noetic = (releases.release(n) for n in ('kinetic', 'melodic', 'noetic'))
    assert kinetic.frame('odom', 'robot') == 'robot/odom'
    assert melodic.frame('link_chassis', '/robot/') == 'robot/link_chassis'
    assert noetic.frame('odom', 'robot') == 'odom'
    assert kinetic.frame('/odom', 'robot') == noetic.frame('/odom', 'robot') == 'odom'
    assert kinetic.frame('odom', '') == 'odom'


def test_legacy_mode_ns_moves_the_pid_gains_on_kinetic_only():
    """gazebo_ros_control's DefaultRobotHWSim reads Gazebo's joint gains under
    /gazebo_ros_control/pid_gains with Kinetic's legacyModeNS (its default,
    #637), else under the robot namespace; Melodic and Noetic always under it (#709)."""
    kinetic = releases.release('kinetic')
    assert kinetic.pid_gains_namespace('robot', None) == '/gazebo_ros_control/pid_gains'
    assert kinetic.pid_gains_namespace('robot', True) == '/gazebo_ros_control/pid_gains'
    assert kinetic.pid_gains_namespace('robot', False) == '/robot/gazebo_ros_control/pid_gains'
    for name in ('melodic', 'noetic'):
        for tag in (None, True, False):
            assert releases.release(name).pid_gains_namespace('robot', tag) == \
                '/robot/gazebo_ros_control/pid_gains'
    assert releases.release('noetic').pid_gains_namespace('', None) == \
        '/gazebo_ros_control/pid_gains'


def test_gazebo_ros_booleans_took_1_and_0_from_melodic_on():
    kinetic, melodic = releases.release('kinetic'), releases.release('melodic')
    assert kinetic.boolean('True', None) == (True, True)
    assert kinetic.boolean('1', False) == (False, False)
    assert melodic.boolean('1', False) == (True, True)
    assert melodic.boolean(None, 'absent') == ('absent', True)


def test_the_parameter_wins_over_the_environment_and_noetic_is_the_default():
    env = {releases.ENV: 'kinetic'}
    assert releases.choose(None, env).name == 'kinetic'
    assert releases.choose('', env).name == 'kinetic'
    assert releases.choose('melodic', env).name == 'melodic'
    assert releases.choose('Noetic', {}).name == 'noetic'
    assert releases.choose(None, {}).name == releases.DEFAULT == 'noetic'


@pytest.mark.parametrize('parameter,environ,where', [('lunar', {}, '~ros_release'),
                                                     (None, {releases.ENV: 'indigo'},
                                                      releases.ENV),
                                                     (3, {}, '~ros_release')])
def test_an_unknown_release_is_refused_in_one_line_naming_the_known_ones(parameter, environ,
                                                                         where):
    with pytest.raises(releases.ReleaseError) as info:
        releases.choose(parameter, environ)
    text = str(info.value)
    assert text.startswith(where + ':') and '\n' not in text
    assert 'kinetic, melodic, noetic' in text


def test_the_engine_refuses_an_unknown_release_and_reports_the_one_it_runs():
    with pytest.raises(releases.ReleaseError):
        Engine(settings={'ros_release': 'jade'})
    engine = Engine(registry=CORES, settings={'ros_release': 'melodic'})
    try:
        assert engine.release.name == 'melodic' and engine.handle.release.name == 'melodic'
    finally:
        engine.close()
    engine = Engine()
    try:
        assert engine.release is releases.RELEASES['noetic']
    finally:
        engine.close()

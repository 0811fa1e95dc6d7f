"""Gazebo's drive plugins keep the last velocity command until another comes,
in every release (the ROS-free cores on the engine, real pybullet, no ROS):
gazebo_ros diff_drive, skid_steer_drive and planar_move have no timeout,
but for Noetic's planar_move ``cmdTimeout`` (#1133); the parameters that bound
a command (wheelAcceleration, wheelTorque, updateRate) are read as Gazebo
read them. A student's wanderer publishing one command a second moved at
half its speed on the simulator's old 0.5 s hold.
"""
import math
import os

import pytest

from exp_assignment2.sim.engine import Engine
from exp_assignment2.sim.plugins.cores import CORES
from fakes import RecordingLog

HERE = os.path.dirname(os.path.abspath(__file__))
DIFF_DRIVE = os.path.join(os.path.dirname(HERE), 'fixtures', 'spawned_robot.urdf')
BALL = os.path.join(os.path.dirname(os.path.dirname(HERE)), 'urdf', 'ball.urdf')
GROUND = ('<robot name="ground"><link name="l"><collision><origin xyz="0 0 -0.05"/><geometry>'
          '<box size="200 200 0.1"/></geometry></collision></link>'
          '<gazebo><static>true</static></gazebo></robot>')
INERTIAL = ('<inertial><mass value="%s"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" '
            'iyz="0" izz="0.01"/></inertial>')
WHEEL = ('<link name="{0}">%s<collision><origin rpy="1.5708 0 0"/><geometry><cylinder '
         'radius="0.06" length="0.03"/></geometry></collision></link><joint name="{0}_joint" '
         'type="continuous"><parent link="base"/><child link="{0}"/><origin xyz="{1} {2} 0"/>'
         '<axis xyz="0 1 0"/></joint>' % (INERTIAL % 0.2))
SKID_STEER = ('<robot name="skid"><gazebo><plugin name="skid" filename="libgazebo_ros_skid_'
              'steer_drive.so"><wheelSeparation>0.3</wheelSeparation><wheelDiameter>0.12'
              '</wheelDiameter><torque>10</torque></plugin></gazebo><link name="base">%s'
              '<collision><geometry><box size="0.4 0.25 0.08"/></geometry></collision></link>%s'
              '</robot>' % (INERTIAL % 3, ''.join(WHEEL.format(*w) for w in (
                  ('left_front', 0.12, 0.15), ('right_front', 0.12, -0.15),
                  ('left_rear', -0.12, 0.15), ('right_rear', -0.12, -0.15)))))


def world(release, settings=None):
    engine = Engine(registry=CORES, log=RecordingLog(), real_time_factor=0,
                    settings=dict(settings or {}, ros_release=release))
    engine.spawn('ground', GROUND)
    return engine


def read(path, **options):
    with open(path) as f:
        text = f.read()
    for tag, value in options.items():
        text = text.replace('<updateRate>', '<%s>%s</%s><updateRate>' % (tag, value, tag), 1)
    return text


def speed(engine, name, seconds=0.5):
    """Mean ground speed (m/s) over the next ``seconds``."""
    (x0, y0, _), _ = engine.models[name].pose()
    engine.run_for(seconds)
    (x1, y1, _), _ = engine.models[name].pose()
    return math.hypot(x1 - x0, y1 - y0) / seconds


@pytest.mark.parametrize('release', ['kinetic', 'melodic', 'noetic'])
@pytest.mark.parametrize('name,text', [('diff', read(DIFF_DRIVE)), ('skid', SKID_STEER)])
def test_one_command_and_ten_seconds_later_the_robot_still_moves(release, name, text):
    engine = world(release)
    try:
        engine.spawn(name, text, (0, 0, 0.07, 0, 0, 0))
        engine.run_for(0.5)
        engine.plugins[name][0].command.command(0.3, 0.0, 0.0)
        engine.run_for(10.0)
        assert speed(engine, name) == pytest.approx(0.3, rel=0.15)
    finally:
        engine.close()


@pytest.mark.parametrize('release,timeout,moving', [
    ('kinetic', None, True), ('melodic', None, True), ('noetic', None, True),
    ('kinetic', 0.5, True), ('melodic', 0.5, True),      # the tag is not read before 2.9.2
    ('noetic', 0.5, False), ('noetic', -1, True)])
def test_the_planar_move_holds_its_command_but_for_noetic_cmd_timeout(release, timeout,
                                                                      moving):
    text = read(BALL)
    if timeout is not None:
        text = text.replace('</plugin>', '<cmdTimeout>%s</cmdTimeout></plugin>' % timeout, 1)
    engine = world(release)
    try:
        engine.spawn('ball', text, (0, 0, 0.5, 0, 0, 0))
        engine.plugins['ball'][0].command.command(0.4, 0.0, 0.0)
        engine.run_for(10.0)
        assert (speed(engine, 'ball') > 0.3) is moving
    finally:
        engine.close()


def test_the_host_hold_stops_a_robot_whose_commands_stop():
    """The package's own launch files keep their hold (cmd_timeout 0.5)."""
    engine = world('noetic', dict(cmd_timeout=0.5))
    try:
        engine.spawn('diff', read(DIFF_DRIVE), (0, 0, 0.07, 0, 0, 0))
        engine.plugins['diff'][0].command.command(0.3, 0.0, 0.0)
        engine.run_for(2.0)
        assert speed(engine, 'diff') < 0.01
    finally:
        engine.close()


def test_wheel_acceleration_ramps_the_wheels_as_gazebo_did():
    engine = world('noetic')
    try:
        for name, accel in (('quick', 0), ('ramped', 0.2)):
            engine.spawn(name, read(DIFF_DRIVE, wheelAcceleration=accel),
                         (0, 2 * len(engine.models), 0.07, 0, 0, 0))
            engine.plugins[name][0].command.command(0.4, 0.0, 0.0)
        engine.run_for(0.3)
        quick, ramped = speed(engine, 'quick', 0.5), speed(engine, 'ramped', 0.5)
        assert quick == pytest.approx(0.4, rel=0.15) and ramped < 0.6 * quick
        engine.run_for(5.0)
        assert speed(engine, 'ramped') == pytest.approx(0.4, rel=0.15)
    finally:
        engine.close()


@pytest.mark.parametrize('tag,value,moves', [
    ('wheelTorque', 0, False),          # fmax 0: the wheels' motors push nothing
    ('updateRate', 0, True),            # 0: every step, as Gazebo's update_period 0
    ('updateRate', -5, True),
    ('wheelSeparation', 0, True),       # Gazebo drives straight on, and cannot turn
])
def test_the_bounding_options_are_read_as_gazebo_read_them(tag, value, moves):
    engine = world('noetic')
    try:
        text = read(DIFF_DRIVE).replace('<%s>' % tag, '<old%s>' % tag).replace(
            '</%s>' % tag, '</old%s>' % tag)
        engine.spawn('diff', read_into(text, tag, value), (0, 0, 0.07, 0, 0, 0))
        assert len(engine.plugins['diff']) == 1
        engine.plugins['diff'][0].command.command(0.3, 0.0, 0.0)
        engine.run_for(1.0)
        assert (speed(engine, 'diff') > 0.2) is moves
    finally:
        engine.close()


def read_into(text, tag, value):
    return text.replace('</plugin>', '<%s>%s</%s></plugin>' % (tag, value, tag), 1)


def test_a_wheel_diameter_of_zero_leaves_the_drive_out_with_gazebo_line():
    engine = world('noetic')
    try:
        text = read(DIFF_DRIVE).replace('<wheelDiameter>0.12', '<wheelDiameter>0')
        engine.spawn('diff', text, (0, 0, 0.07, 0, 0, 0))
        assert engine.plugins['diff'] == [] and 'diff' in engine.models
        assert [t for level, t in engine.log.lines if level == 'error'] == [
            "model diff: plugin drive (libgazebo_ros_diff_drive.so): <wheelDiameter> "
            "must be other than 0, got '0'; Exception occured in the Load function of plugin "
            "with name[drive] and filename[libgazebo_ros_diff_drive.so]. This plugin will not "
            "run."]
    finally:
        engine.close()

"""What Gazebo 11 spawns from a URDF, the engine spawns (exp_assignment2.sim.urdf
and .urdf_masses), no ROS: massless links as sdformat's URDF reader models
them (fixed-joint reduction, then no link without mass), one warning line per
link left out; a static model's masses are not checked; what would break the
world stays refused. The world's models and /gazebo/spawn_urdf_model both
spawn through Engine.spawn, which is what these tests call.
"""
import os

import pytest

from exp_assignment2.sim.bullet import p
from exp_assignment2.sim.engine import Engine, SpawnError
from exp_assignment2.sim.sdf import read_world
from fakes import RecordingLog

SAVED = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'data',
                     'worlds', 'saved_shelter.world')

INERTIAL = ('<inertial><mass value="%s"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" '
            'iyz="0" izz="0.01"/></inertial>')
GROUND = ('<robot name="ground"><link name="l"><collision><origin xyz="0 0 -0.05"/><geometry>'
          '<box size="20 20 0.1"/></geometry></collision></link>'
          '<gazebo><static>true</static></gazebo></robot>')


def robot(footprint=None, wheel='0.2', tail='', gazebo=''):
    """REP 105's shape: a base_footprint root fixed to base_link, two wheels."""
    def inertial(mass):
        return '' if mass is None else INERTIAL % mass
    return '''<robot name="r">
      <link name="base_footprint">%s</link>
      <link name="base_link">%s<collision><geometry><box size="0.4 0.3 0.1"/></geometry>
        </collision></link>
      <joint name="footprint" type="fixed"><parent link="base_footprint"/>
        <child link="base_link"/><origin xyz="0 0 0.1"/></joint>
      <link name="left">%s<collision><geometry><sphere radius="0.05"/></geometry></collision>
        </link>
      <joint name="j_left" type="continuous"><parent link="base_link"/><child link="left"/>
        <origin xyz="0 0.2 0"/><axis xyz="0 1 0"/></joint>
      <link name="right">%s<collision><geometry><sphere radius="0.05"/></geometry></collision>
        </link>
      <joint name="j_right" type="continuous"><parent link="base_link"/><child link="right"/>
        <origin xyz="0 -0.2 0"/><axis xyz="0 1 0"/></joint>
      %s%s
    </robot>''' % (inertial(footprint), inertial(2), inertial(wheel), inertial(0.2), tail,
                   gazebo)


@pytest.fixture
def engine():
    eng = Engine(log=RecordingLog(), real_time_factor=0)
    eng.spawn('ground', GROUND)
    yield eng
    eng.close()


def warnings(engine):
    return [text for level, text in engine.log.lines if level == 'warn']


def total_mass(engine, model):
    return sum(p.getDynamicsInfo(model.id, index, physicsClientId=engine.physics.client)[0]
               for index in model.body.links.values())


def test_a_root_without_inertial_adds_no_mass_and_the_robot_moves(engine):
    # pybullet gives a link without <inertial> 1 kg; Gazebo lumps base_link into it
    model = engine.spawn('r', robot(), (0, 0, 1, 0, 0, 0))
    assert total_mass(engine, model) == pytest.approx(2.4, abs=0.01)
    engine.run_for(2.0)
    assert model.pose()[0][2] == pytest.approx(-0.05, abs=0.01)     # it fell and rests
    assert warnings(engine) == []


def test_a_massless_frame_on_a_fixed_joint_rides_on_its_parent_adding_no_mass(engine):
    tail = ('<link name="camera_optical"/><joint name="optical" type="fixed"><parent '
            'link="base_link"/><child link="camera_optical"/><origin xyz="0.2 0 0.1"/></joint>')
    model = engine.spawn('r', robot(footprint='1', tail=tail), (0, 0, 1, 0, 0, 0))
    assert 'camera_optical' in model.body.links
    assert total_mass(engine, model) == pytest.approx(3.4, abs=0.01)
    assert warnings(engine) == []


def test_a_massless_link_on_a_moving_joint_is_left_out_with_one_line(engine):
    tail = ('<link name="hub"/><joint name="j_hub" type="fixed"><parent link="left"/>'
            '<child link="hub"/></joint>')
    model = engine.spawn('r', robot(footprint='1', wheel=None, tail=tail), (0, 0, 1, 0, 0, 0))
    assert sorted(model.body.links) == ['base_footprint', 'base_link', 'right']
    assert 'j_left' not in model.urdf.joints
    assert warnings(engine) == [
        "model r: link left: no mass (no <inertial>, or mass 0) on continuous joint j_left: "
        "Gazebo does not model it (sdformat: 'has no inertia, not modeled in sdf'), nor the "
        "links below it: hub; left out here too"]


def test_a_moving_link_below_a_massless_fixed_link_is_left_out_as_gazebo_stops_there(engine):
    tail = ('<link name="mount"/><joint name="j_mount" type="fixed"><parent link="base_link"/>'
            '<child link="mount"/><origin xyz="0.1 0 0.05"/></joint>'
            '<link name="arm">%s</link><joint name="j_arm" type="revolute"><parent link="mount"/>'
            '<child link="arm"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" '
            'velocity="1"/></joint>' % (INERTIAL % 0.3))
    model = engine.spawn('r', robot(footprint='1', tail=tail), (0, 0, 1, 0, 0, 0))
    assert 'mount' in model.body.links and 'arm' not in model.body.links
    assert warnings(engine) == [
        "model r: link mount: no mass on fixed joint j_mount: Gazebo lumps it into link "
        "base_link and models nothing that moves below it (sdformat: 'has no inertia, not "
        "modeled in sdf'): links arm left out here too"]


def test_a_dynamic_model_with_no_mass_at_its_root_is_refused(engine):
    text = robot().replace(INERTIAL % 2, '')
    with pytest.raises(SpawnError) as err:
        engine.spawn('r', text)
    assert str(err.value) == (
        "model r: link base_footprint: the root link of a dynamic model has no mass (no "
        "<inertial>, or mass 0), nor has any link fixed to it: Gazebo would model none of the "
        "robot (sdformat: 'has no inertia, not modeled in sdf'); give it an <inertial>, or make "
        "the model static (<gazebo><static>true</static></gazebo>)")
    assert 'r' not in engine.models


@pytest.mark.parametrize('gazebo', [
    '<gazebo><static>true</static></gazebo>',
    '<gazebo reference="base_footprint"><gravity>0</gravity></gazebo>',     # kinematic
])
def test_a_static_or_kinematic_model_masses_are_not_checked(engine, gazebo):
    text = robot(wheel=None, gazebo=gazebo).replace(INERTIAL % 2, '').replace(
        INERTIAL % 0.2, '')
    model = engine.spawn('r', text)
    assert sorted(model.body.links) == ['base_footprint', 'base_link', 'left', 'right']
    assert warnings(engine) == []


@pytest.mark.parametrize('old,new,message', [
    (INERTIAL % 2, INERTIAL % -2, "model r: link base_link: mass -2 is negative (Gazebo's ODE "
                                  "refuses it: 'Setting custom link ... mass to zero!')"),
    ('<box size="0.4 0.3 0.1"/>', '<box size="1e30 1e30 1e30"/>',
     'model r: link base_link collision: <box> size 1e+30 1e+30 1e+30: each must be in '
     '[0, 10000]'),
])
def test_what_would_break_the_world_is_still_refused(engine, old, new, message):
    text = robot()
    assert old in text
    with pytest.raises(SpawnError) as err:
        engine.spawn('r', text.replace(old, new))
    assert str(err.value) == message


def test_an_sdf_world_massless_flag_is_said_once_by_the_sdf_reader_not_again(engine):
    world = read_world(SAVED, model_path=[])
    assert len(world.warnings) == 1
    for model in world.models:
        engine.spawn(model.name, model.urdf, model.pose)
    assert warnings(engine) == []


def test_a_root_called_world_is_gazebo_world_not_a_massless_link(engine):
    text = ('<robot name="arm"><link name="world"/>'
            '<link name="base">%s<collision><geometry><box size="0.2 0.2 0.2"/></geometry>'
            '</collision></link><joint name="to_world" type="fixed"><parent link="world"/>'
            '<child link="base"/></joint>'
            '<link name="label"/><joint name="to_label" type="fixed"><parent link="world"/>'
            '<child link="label"/></joint></robot>' % (INERTIAL % 1))
    model = engine.spawn('arm', text, (0, 0, 1, 0, 0, 0))
    assert sorted(model.body.links) == ['base', 'world']
    assert warnings(engine) == [
        "model arm: link label: no mass (no <inertial>, or mass 0) on fixed joint to_label: "
        "Gazebo does not model it (sdformat: 'has no inertia, not modeled in sdf'); left out "
        "here too"]

"""A URDF read as urdfdom reads it, and spawned as Gazebo builds it
(exp_assignment2.sim.urdf, .urdf_elements, .urdf_links), no ROS.

urdfdom reads no axis of a fixed or floating joint; it reads a moving joint's
zero axis, which Gazebo's ODE makes the world's x; it refuses the URDF for a
joint it cannot read, but only drops a link's element it cannot read (with
the elements after it) and goes on. Each case below is a row of the table in
docs/simulator.md ("What the simulator refuses").
"""
import math

import numpy as np
import pytest

from exp_assignment2.sim.bullet import p
from exp_assignment2.sim.engine import Engine, SpawnError
from fakes import RecordingLog

INERTIAL = ('<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" '
            'iyz="0" izz="0.01"/></inertial>')
BOX = '<collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>'


def robot(joint='type="fixed"', child='', axis=''):
    """A body and a head on joint ``neck``."""
    return ('<robot name="r"><link name="body">%s%s</link><link name="head">%s%s</link>'
            '<joint name="neck" %s><parent link="body"/><child link="head"/><origin '
            'xyz="0 0 0.3"/>%s</joint></robot>' % (INERTIAL, BOX, INERTIAL, child, joint, axis))


@pytest.fixture
def engine():
    eng = Engine(log=RecordingLog(), real_time_factor=0)
    yield eng
    eng.close()


def lines(engine, level):
    return [text for lvl, text in engine.log.lines if lvl == level]


@pytest.mark.parametrize('joint,axis', [
    ('type="fixed"', '<axis xyz="0 0 0"/>'),          # the student's neck, made fixed
    ('type="fixed"', '<axis xyz="1 0"/>'),            # not even three numbers
    ('type="floating"', '<axis xyz="0 0 0"/>'),
])
def test_a_fixed_or_floating_joint_axis_is_not_read(engine, joint, axis):
    model = engine.spawn('r', robot(joint, axis=axis))
    assert sorted(model.body.links) == ['body', 'head']
    assert engine.log.lines == []


def test_a_moving_joint_zero_axis_is_the_world_x_at_the_spawn(engine):
    yaw = math.pi / 2
    model = engine.spawn('r', robot('type="continuous"', axis='<axis xyz="0 0 0"/>'),
                         (0, 0, 1, 0, 0, yaw))
    # world x seen from a joint turned a quarter to the left is its -y
    assert model.urdf.joints['neck'].axis == pytest.approx([0, -1, 0], abs=1e-9)
    info = p.getJointInfo(model.id, model.body.joints['neck'][0],
                          physicsClientId=engine.physics.client)
    assert np.array(info[13]) == pytest.approx([0, -1, 0], abs=1e-9)
    assert lines(engine, 'warn') == [
        "model r: joint neck: the axis is 0 0 0: urdfdom reads it and Gazebo's ODE turns the "
        "continuous joint about the world's x axis as the model was spawned (axis 6.12e-17 -1 "
        "0 in the joint's frame); so does the simulator"]


@pytest.mark.parametrize('joint,axis,message', [
    ('type="hinge"', '', 'Joint [neck] has no known type [hinge] (urdfdom knows revolute, '
                         'continuous, prismatic, planar, fixed, floating)'),
    ('type="revolute"', '<axis xyz="0 0 1"/>',
     'Joint [neck] is of type REVOLUTE but it does not specify limits'),
    ('type="prismatic"', '<axis xyz="0 0 1"/>',
     'Joint [neck] is of type PRISMATIC without limits'),
    ('type="continuous"', '<axis xyz="0 1"/>', "Malformed axis element for joint [neck]: "
                                               "joint neck axis: expected 3 finite numbers, "
                                               "got '0 1'"),
    ('type="revolute"', '<limit lower="-a" upper="1" effort="1" velocity="1"/>',
     'lower value (-a) is not a valid float'),
])
def test_a_joint_urdfdom_cannot_read_refuses_the_robot_in_its_words(engine, joint, axis,
                                                                      message):
    with pytest.raises(SpawnError) as err:
        engine.spawn('r', robot(joint, axis=axis))
    assert str(err.value) == 'model r: joint neck: ' + message
    assert 'r' not in engine.models


@pytest.mark.parametrize('child,dropped,line', [
    ('<visual><geometry><cone radius="1"/></geometry></visual>' + BOX, (1, 1),
     "link head visual: Unknown geometry type 'cone'; Could not parse visual element for Link "
     "[head] (urdfdom stops reading the link there, and Gazebo builds it as read): 1 visual, 1 "
     "collision left out here too"),
    ('<visual><geometry><sphere radius="0.1"/></geometry><material><color rgba="1 0 0 1"/>'
     '</material></visual>' + BOX, (1, 1),
     'link head visual: Visual material must contain a name attribute; Could not parse visual '
     'element for Link [head] (urdfdom stops reading the link there, and Gazebo builds it as '
     'read): 1 visual, 1 collision left out here too'),
    ('<visual><origin xyz="0 0 nan"/><geometry><sphere radius="0.1"/></geometry></visual>',
     (1, 0), 'link head visual xyz: expected 3 finite numbers, got \'0 0 nan\'; Could not '
     'parse visual element for Link [head] (urdfdom stops reading the link there, and Gazebo '
     'builds it as read): 1 visual left out here too'),
    (BOX + '<collision><geometry/></collision>', (0, 1),
     'link head collision: Geometry tag contains no child element.; Could not parse collision '
     'element for Link [head] (urdfdom stops reading the link there, and Gazebo builds it as '
     'read): 1 collision left out here too'),
])
def test_a_link_element_urdfdom_cannot_read_is_dropped_with_what_follows(engine, child,
                                                                         dropped, line):
    model = engine.spawn('r', robot(child=child))
    head = model.urdf.links['head']
    visuals, collisions = child.count('<visual>'), child.count('<collision>')
    assert (len(head.visuals), len(head.collisions)) == (visuals - dropped[0],
                                                         collisions - dropped[1])
    assert lines(engine, 'error') == ['model r: ' + line]
    assert 'head' in model.body.links


def test_an_inertial_without_inertia_keeps_its_mass_and_drops_the_shapes(engine):
    text = robot('type="continuous"', child=BOX, axis='<axis xyz="0 1 0"/>').replace(
        '<link name="head">' + INERTIAL, '<link name="head"><inertial><mass value="0.5"/>'
                                         '</inertial>')
    model = engine.spawn('r', text)
    assert model.urdf.links['head'].mass == 0.5 and model.urdf.links['head'].collisions == []
    info = p.getDynamicsInfo(model.id, model.body.links['head'],
                             physicsClientId=engine.physics.client)
    assert info[0] == pytest.approx(0.5)
    assert lines(engine, 'error') == [
        'model r: link head inertial: Inertial element must have inertia element; Could not '
        'parse inertial element for Link [head] (urdfdom stops reading the link there, and '
        'Gazebo builds it as read): 1 collision left out here too']


def test_a_mass_urdfdom_cannot_read_leaves_the_link_massless_as_gazebo_models_it(engine):
    text = robot('type="continuous"', child=BOX, axis='<axis xyz="0 1 0"/>').replace(
        '<link name="head">' + INERTIAL, '<link name="head">' + INERTIAL.replace('"1"', '"nan"'))
    model = engine.spawn('r', text)
    assert sorted(model.body.links) == ['body']
    assert lines(engine, 'error')[0].startswith(
        'model r: link head inertial: Inertial: mass [nan] is not a valid double; Could not '
        'parse inertial element for Link [head]')
    assert lines(engine, 'warn')[0].startswith('model r: link head: no mass')


def test_a_bad_colour_is_said_and_the_visual_drawn_without_it(engine):
    child = ('<visual><geometry><sphere radius="0.1"/></geometry><material name="m"><color '
             'rgba="2 0 0 1"/></material></visual>')
    model = engine.spawn('r', robot(child=child))
    assert model.urdf.links['head'].visuals[0].rgba == (1.0, 1.0, 1.0, 1.0)
    assert lines(engine, 'error') == [
        "model r: link head visual: Material [m] has malformed color rgba values: '2 0 0 1' "
        "(urdfdom: 4 numbers in [0, 1]); drawn without it"]


def test_a_mesh_whose_file_is_missing_is_left_out_with_gazebo_line(engine, tmp_path):
    child = ('<visual><geometry><mesh filename="meshes/head.stl"/></geometry></visual>'
             '<collision><geometry><mesh filename="meshes/head.stl"/></geometry></collision>')
    model = engine.spawn('r', robot(child=child), base_dir=str(tmp_path))
    head = model.urdf.links['head']
    assert head.visuals == [] and head.collisions == []
    path = str(tmp_path / 'meshes' / 'head.stl')
    assert lines(engine, 'error') == [
        'model r: link head visual: Unable to find file[%s]: Gazebo draws nothing for it; left '
        'out here too' % path,
        'model r: link head collision: Unable to find file[%s]: Gazebo collides with nothing '
        'for it; left out here too' % path]


def test_a_mesh_pybullet_cannot_read_is_left_out_not_the_robot(engine, tmp_path):
    (tmp_path / 'head.ply').write_text('ply\n')
    child = '<visual><geometry><mesh filename="head.ply"/></geometry></visual>'
    model = engine.spawn('r', robot(child=child), base_dir=str(tmp_path))
    assert model.urdf.links['head'].visuals == []
    assert lines(engine, 'error') == [
        'model r: link head visual: a .ply mesh (%s) is not read here (STL, OBJ and COLLADA '
        'are): left out; Gazebo draws it if it reads the format, else logs "Invalid mesh '
        'filename extension"' % (tmp_path / 'head.ply')]


@pytest.mark.parametrize('text,message', [
    ('<robot name="r"><link name="a">', 'not a valid URDF: no element found: line 1, column 31'),
    ('<sdf version="1.6"/>', 'not a URDF: the root element is <sdf>, not <robot>'),
    ('<robot name="r"/>', 'robot r has no link'),
    ('<robot name="r"><link/></robot>', 'robot r: a link has no name'),
    (robot().replace('<child link="head"/>', '<child link="hat"/>'), "joint neck: no link "
                                                                       "'hat'"),
    (robot().replace('<joint', '<link name="tail"/><joint'),
     'robot r: 2 root links (body, tail); a URDF is one tree'),
    (robot(child='<visual><geometry><box size="-1 1 1"/></geometry></visual>'),
     'link head visual: <box> size -1 1 1: each must be in [0, 10000]'),
])
def test_what_urdfdom_refuses_or_would_break_the_world_is_refused(engine, text, message):
    with pytest.raises(SpawnError) as err:
        engine.spawn('r', text)
    assert str(err.value) == 'model r: ' + message

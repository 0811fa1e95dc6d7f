"""SDF models read into URDF (exp_assignment2.sim.sdf), no ROS: includes
(Gazebo's stock models, the size table's, installed and nested ones),
joints, sensors and plugins, and what spawn_model -sdf sends."""
import xml.etree.ElementTree as ET

import pytest

from exp_assignment2.sim.sdf import model_pose, model_to_urdf, read_world
from sdf_helpers import ARM, box_model, only, shape, world


# includes

def test_what_gazebo_makes_but_the_simulator_does_not_is_skipped_with_a_note():
    w = read_world(world(box_model('m') + "<actor name='walker'><skin/></actor>"
                         "<plugin name='p' filename='libworld_thing.so'/>"
                         "<light name='lamp' type='point'/>"), model_path=[])
    assert [m.name for m in w.models] == ['m']
    assert w.notes == ['world/actor[walker]: animated actors are not simulated here: skipped',
                       'world/plugin[p]: world plugins are not simulated here: skipped']


def test_gazebo_stock_includes_ground_plane_and_sun():
    w = read_world(world('<include><uri>model://ground_plane</uri></include>'
                         '<include><uri>model://sun</uri></include>'), model_path=[])
    assert [m.name for m in w.models] == ['ground_plane']
    urdf = ET.fromstring(w.models[0].urdf)
    assert shape(urdf) == ('box', {'size': '100 100 0.02'}) and w.models[0].static


def test_an_include_of_a_known_model_is_its_box_with_the_include_name_and_pose():
    w = read_world(world("<include><uri>model://jersey_barrier</uri><name>wall_1</name>"
                         "<pose>1 2 0 0 0 1.57</pose></include>"), model_path=[])
    (m,) = w.models
    assert m.name == 'wall_1' and m.static and m.pose == pytest.approx((1, 2, 0, 0, 0, 1.57))
    urdf = ET.fromstring(m.urdf)
    assert shape(urdf, 'collision') == ('box', {'size': '4.0656 0.8128 1.143'})
    assert urdf.find('link/inertial/mass').get('value') == '4000'
    assert w.notes[0].startswith('model://jersey_barrier is not installed: a 4.07 x 0.81 x 1.14')


def test_installed_models_and_nested_includes_are_flattened(tmp_path):
    inner = tmp_path / 'lamp'
    inner.mkdir()
    (inner / 'model.sdf').write_text("<sdf version='1.6'>%s</sdf>" % box_model(
        'lamp', '<sphere><radius>0.1</radius></sphere>').replace('<static>1</static>', ''))
    outer = tmp_path / 'desk'
    outer.mkdir()
    (outer / 'model.config').write_text('<model><name>desk</name><sdf>desk.sdf</sdf></model>')
    (outer / 'desk.sdf').write_text(
        "<sdf version='1.6'><model name='desk'><link name='top'><visual name='v'><geometry>"
        "<box><size>1 1 0.1</size></box></geometry></visual></link>"
        "<include><uri>model://lamp</uri><pose>0.3 0 0.5 0 0 0</pose></include></model></sdf>")
    w = read_world(world("<include><uri>model://desk</uri><pose>5 0 0 0 0 0</pose></include>"),
                   model_path=[str(tmp_path)])
    (m,) = w.models
    urdf = ET.fromstring(m.urdf)
    assert [l.get('name') for l in urdf.findall('link')] == ['top', 'lamp::link']
    joint = urdf.find('joint')
    assert joint.get('type') == 'fixed' and joint.find('child').get('link') == 'lamp::link'
    assert joint.find('origin').get('xyz') == '0.3 0 0.5'
    assert m.pose == pytest.approx((5, 0, 0, 0, 0, 0)) and not m.static



@pytest.mark.parametrize('flag, rests', [('', True), ('<allow_auto_disable>0</allow_auto_disable>',
                                                       False)])
def test_allow_auto_disable_comes_through_as_gazebo_reads_it(flag, rests):
    from exp_assignment2.sim import gazebo_tags
    model, urdf = only(box_model('barrel').replace('<static>1</static>', flag))
    assert gazebo_tags.read(urdf).auto_disable is rests


# joints, plugins, sensors




def test_a_jointed_model_keeps_its_joints_sensors_and_plugins():
    urdf = ET.fromstring(model_to_urdf(ARM, 'arm_1'))
    assert urdf.get('name') == 'arm_1'
    joint = urdf.find('joint')
    assert (joint.get('name'), joint.get('type')) == ('shoulder', 'revolute')
    # the joint frame is the child's pose composed with the joint's own pose
    assert joint.find('origin').get('xyz') == '0 0 0.2'
    assert joint.find('axis').get('xyz') == '0 1 0'
    assert joint.find('limit').attrib == {'effort': '20', 'velocity': '2', 'lower': '-1',
                                          'upper': '1.5'}
    upper = [l for l in urdf.findall('link') if l.get('name') == 'upper'][0]
    assert upper.find('visual/origin').get('xyz') == '0 0 0.3'
    plugin = urdf.find('gazebo/plugin')
    assert plugin.get('filename') == 'libgazebo_ros_control.so'
    sensor = urdf.find("gazebo[@reference='upper']/sensor")
    assert sensor.get('type') == 'camera' and sensor.findtext('update_rate') == '15'
    assert sensor.findtext('pose') == '0.1 0 0.3 0 0 0'


def test_a_revolute_joint_without_limits_is_continuous():
    text = ARM.replace('<limit><lower>-1</lower><upper>1.5</upper>', '<limit>')
    joint = ET.fromstring(model_to_urdf(text)).find('joint')
    assert joint.get('type') == 'continuous'
    assert joint.find('limit').attrib == {'effort': '20', 'velocity': '2'}


def test_spawn_sdf_forms_model_database_include_and_own_pose():
    notes = []
    database = ("<sdf version='1.4'><world name='default'><include><uri>model://jersey_barrier"
                "</uri></include></world></sdf>")
    urdf = ET.fromstring(model_to_urdf(database, 'barrier', model_path=[], notes=notes))
    assert urdf.get('name') == 'barrier' and urdf.find('gazebo/static').text == 'true'
    assert len(notes) == 1 and 'model://jersey_barrier is not installed' in notes[0]
    assert model_pose("<sdf version='1.6'>%s</sdf>" % box_model('b', pose='1 2 3 0 0 0.5')) == \
        pytest.approx((1, 2, 3, 0, 0, 0.5))

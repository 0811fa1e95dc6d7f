"""A URDF's <gazebo> tags read as Gazebo reads them, and plugin options
(no ROS, no pybullet)."""
import os

import pytest

from exp_assignment2.sim import urdf
from exp_assignment2.sim.gazebo_materials import GAZEBO_MATERIALS
from exp_assignment2.sim.plugins.base import Options, PluginError

URDF_DIR = os.path.join(os.path.dirname(__file__), '..', '..', 'urdf')

ROBOT = '''<robot name="r">
  <gazebo reference="base"><material>Gazebo/Red</material><mu1>0.7</mu1></gazebo>
  <gazebo reference="wheel"><turnGravityOff>true</turnGravityOff></gazebo>
  <gazebo reference="cam">
    <sensor type="camera" name="camera1">
      <update_rate>15.0</update_rate>
      <pose>0.1 0 0 0 0 0</pose>
      <camera name="head">
        <horizontal_fov>1.2</horizontal_fov>
        <image><width>320</width><height>240</height><format>R8G8B8</format></image>
        <clip><near>0.02</near><far>300</far></clip>
      </camera>
      <plugin name="camera_controller" filename="libgazebo_ros_camera.so">
        <cameraName>cam1</cameraName>
        <imageTopicName>image_raw</imageTopicName>
      </plugin>
    </sensor>
  </gazebo>
  <gazebo>
    <plugin name="dd" filename="libgazebo_ros_diff_drive.so">
      <!-- a comment -->
      <leftJoint>j_left</leftJoint>
      <legacyMode>true</legacyMode>
    </plugin>
  </gazebo>
  <gazebo><static>false</static></gazebo>
  <link name="base"><inertial><mass value="2"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0"
    izz="1"/></inertial><visual><geometry><box size="1 1 1"/>
    </geometry><material name="blue"><color rgba="0 0 1 1"/></material></visual></link>
  <link name="wheel"><inertial><mass value="0.1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1"
    iyz="0" izz="1"/></inertial></link>
  <link name="cam"/>
  <joint name="j_left" type="continuous"><parent link="base"/><child link="wheel"/>
    <origin xyz="0 0.2 0"/><axis xyz="0 1 0"/></joint>
  <joint name="j_cam" type="fixed"><parent link="base"/><child link="cam"/></joint>
</robot>'''


def test_plugins_sensors_colours_and_flags():
    model = urdf.parse(ROBOT)
    tags = model.gazebo
    assert [(p.name, p.filename, p.reference) for p in tags.plugins] == [
        ('camera_controller', 'libgazebo_ros_camera.so', 'cam'),
        ('dd', 'libgazebo_ros_diff_drive.so', None)]
    camera = tags.plugins[0]
    assert camera.options == {'cameraName': 'cam1', 'imageTopicName': 'image_raw'}
    sensor = camera.sensor
    assert (sensor.type, sensor.name, sensor.link, sensor.update_rate) == (
        'camera', 'camera1', 'cam', 15.0)
    assert sensor.pose == (0.1, 0, 0, 0, 0, 0)
    assert sensor.options['camera']['image'] == {'width': '320', 'height': '240',
                                                 'format': 'R8G8B8'}
    assert tags.plugins[1].options == {'leftJoint': 'j_left', 'legacyMode': 'true'}
    assert tags.colours == {'base': GAZEBO_MATERIALS['Gazebo/Red']}
    # Gazebo draws a link in its Gazebo material, whatever the URDF's colour
    assert model.links['base'].visuals[0].rgba == GAZEBO_MATERIALS['Gazebo/Red']
    assert tags.gravity_off == {'wheel'} and tags.friction == {'base': (0.7, None)}
    assert not tags.static and tags.warnings == [] and model.warnings == []


def test_the_package_robots_name_their_plugins():
    for name, filenames in (('robot.urdf', ['libgazebo_ros_diff_drive.so',
                                            'libgazebo_ros_camera.so',
                                            'libgazebo_ros_control.so']),
                            ('ball.urdf', ['libgazebo_ros_planar_move.so']),
                            ('miro.urdf', ['libgazebo_ros_planar_move.so']),
                            ('arena.urdf', [])):
        with open(os.path.join(URDF_DIR, name)) as f:
            model = urdf.parse(f.read(), URDF_DIR)
        assert [p.filename for p in model.gazebo.plugins] == filenames, name
    assert model.gazebo.static


def test_what_gazebo_would_not_understand_is_a_warning_not_a_failure():
    text = ROBOT.replace('Gazebo/Red', 'Gazebo/Sparkly').replace(
        '<gazebo reference="wheel">', '<gazebo reference="nowhere">')
    model = urdf.parse(text)
    assert model.links['base'].visuals[0].rgba == GAZEBO_MATERIALS['Gazebo/Grey']
    assert any("'Gazebo/Sparkly' is not known" in w for w in model.gazebo.warnings)
    assert model.warnings == ['<gazebo reference="nowhere">: no link or joint of that name; '
                              'ignored']


@pytest.mark.parametrize('text,why', [
    ('<robot name="x"><link name="a"/><link name="b"/></robot>', '2 root links'),
    ('<robot name="x"><link name="a"/><joint name="j" type="fixed"><parent link="a"/>'
     '<child link="c"/></joint></robot>', "no link 'c'"),
    # (a link's elements urdfdom cannot read are dropped, not refused:
    # test_urdf_urdfdom_reads.py)
    # sizes pybullet cannot hold (a 1e30 m box threw every body out of the world)
    ('<robot name="x"><link name="a"><collision><geometry><box size="1e30 1e30 1e30"/>'
     '</geometry></collision></link></robot>',
     r'link a collision: <box> size 1e\+30 1e\+30 1e\+30: each must be in \[0, 10000\]'),
    ('<robot name="x"><link name="a"><visual><geometry><sphere radius="-1"/></geometry>'
     '</visual></link></robot>', r'<sphere> radius -1: each must be in'),
    ('<robot name="x"><link name="a"><inertial><mass value="-5"/></inertial></link></robot>',
     'link a: mass -5 is negative'),
])
def test_a_bad_urdf_is_refused_with_the_reason(text, why):
    with pytest.raises(urdf.UrdfError, match=why):
        urdf.parse(text)


def test_joint_axes_and_frames_in_the_root_frame():
    model = urdf.parse(ROBOT)
    position, axis = model.joint_axis_in_root('j_left')
    assert tuple(position) == (0, 0.2, 0) and tuple(axis) == (0, 1, 0)


def test_options_are_typed_and_say_what_was_wrong():
    o = Options({'rate': '20', 'on': 'true', 'off': '0', 'name': ' x ', 'bad': 'fast',
                 'nested': {'a': '1'}}, 'model m: plugin p')
    assert o.number('rate', 1.0) == 20.0 and o.number('missing', 3.0) == 3.0
    assert o.boolean('on', False) is True and o.boolean('off', True) is False
    assert o.text('name') == 'x' and o.text('nested', 'd') == 'd'
    assert o.raw('nested') == {'a': '1'}
    assert o.number('bad', 1.0) == 0.0       # as a C++ stream reads it, with a note
    assert o.notes == ["model m: plugin p: <bad> 'fast' is not a number: Gazebo reads it as 0"]
    with pytest.raises(PluginError, match='must be true or false'):
        o.boolean('bad', True)
    with pytest.raises(PluginError, match='must be positive'):
        Options({'r': '0'}, 'w').number('r', 1.0, positive=True)
    with pytest.raises(PluginError, match='must be other than 0'):
        Options({'r': 'inf'}, 'w').number('r', 1.0, nonzero=True)
    assert Options({'r': '0.3 m'}, 'w').number('r', 1.0) == 0.3


def test_one_colour_per_gazebo_material_in_urdf_and_sdf():
    """A Gazebo/Wood URDF link and a Gazebo/Wood SDF visual are drawn alike,
    and untextured materials take gazebo.material's diffuse."""
    import xml.etree.ElementTree as ET
    from exp_assignment2.sim import gazebo_tags, sdf_geometry
    for name in ('Gazebo/Wood', 'Gazebo/Gold', 'Gazebo/Orange', 'Gazebo/ZincYellow'):
        tags = gazebo_tags.read(ET.fromstring(
            '<robot><gazebo reference="base"><material>%s</material></gazebo></robot>' % name))
        visual = ET.fromstring('<visual><material><script><name>%s</name></script></material>'
                               '</visual>' % name)
        sdf = sdf_geometry.colour_of(visual, 'v')
        assert sdf == tags.colours['base'] == GAZEBO_MATERIALS[name]
    assert GAZEBO_MATERIALS['Gazebo/Orange'] == (1.0, 0.5088, 0.0468, 1.0)
    assert GAZEBO_MATERIALS['Gazebo/Gold'] == (0.8, 0.64869, 0.120759, 1.0)

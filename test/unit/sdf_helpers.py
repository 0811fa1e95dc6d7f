"""Helpers of the SDF reader's tests (test_sdf.py, test_sdf_models.py): small
SDF documents, and what the URDF text made of them says."""
import textwrap
import xml.etree.ElementTree as ET

from exp_assignment2.sim.sdf import read_world


def world(body, version='1.6'):
    return "<sdf version='%s'><world name='w'>%s</world></sdf>" % (version, body)


def box_model(name, geometry='<box><size>1 2 3</size></box>', extra='', pose='0 0 0 0 0 0'):
    return textwrap.dedent("""
        <model name='%s'><static>1</static><pose>%s</pose><link name='link'>%s
          <visual name='visual'><geometry>%s</geometry></visual>
          <collision name='collision'><geometry>%s</geometry></collision>
        </link></model>""") % (name, pose, extra, geometry, geometry)


def only(text, **kw):
    models = read_world(world(text), model_path=[], **kw).models
    assert len(models) == 1
    return models[0], ET.fromstring(models[0].urdf)


def shape(urdf, part='visual'):
    elem = urdf.find('link/%s/geometry' % part)[0]
    return elem.tag, dict(elem.attrib)


def origin(urdf, part='visual'):
    o = urdf.find('link/%s/origin' % part)
    return [float(v) for v in o.get('xyz').split()], [float(v) for v in o.get('rpy').split()]


def rgba(urdf):
    return tuple(float(v) for v in urdf.find('link/visual/material/color').get('rgba').split())


# a model with two links, a joint, a sensor and a plugin
ARM = """<sdf version='1.6'><model name='arm'>
  <link name='base'><visual name='v'><geometry><box><size>0.2 0.2 0.2</size></box></geometry>
  </visual></link>
  <link name='upper'><pose>0 0 0.5 0 0 0</pose>
    <visual name='v'><geometry><cylinder><radius>0.05</radius><length>0.6</length></cylinder>
    </geometry></visual>
    <sensor name='cam' type='camera'><pose>0.1 0 0 0 0 0</pose><update_rate>15</update_rate>
      <plugin name='c' filename='libgazebo_ros_camera.so'><cameraName>cam</cameraName></plugin>
    </sensor></link>
  <joint name='shoulder' type='revolute'><parent>base</parent><child>upper</child>
    <pose>0 0 -0.3 0 0 0</pose>
    <axis><xyz>0 1 0</xyz><limit><lower>-1</lower><upper>1.5</upper><effort>20</effort>
    <velocity>2</velocity></limit></axis></joint>
  <plugin name='ctl' filename='libgazebo_ros_control.so'><robotNamespace>/arm</robotNamespace>
  </plugin>
</model></sdf>"""

"""A read SDF model (:mod:`~exp_assignment2.sim.sdf_model`) written as URDF text
(plain Python: no ROS, no pybullet).

:func:`model_urdf` writes a URDF robot whose root link frame is the model frame
(URDF has no model pose: the spawn pose places it), with a joint per SDF joint,
links that have no joint fixed to the root, ``<gazebo><static>true</static></gazebo>``
for a static model, and the model's ``<plugin>`` and the links' ``<sensor>``
elements carried over in ``<gazebo>`` tags, as Gazebo's URDF reader expects them.
"""
import copy
import xml.etree.ElementTree as ET

import numpy as np

from exp_assignment2.sim.sdf_geometry import SdfError, pose_tuple
from exp_assignment2.sim.sdf_model import DEFAULT_EFFORT, DEFAULT_VELOCITY, NO_LIMIT


def model_urdf(model):
    """URDF text of a :class:`Model` (its own pose is left out)."""
    links = list(model.links.values())
    root = links[0]
    frames = {root.name: np.eye(4)}             # each link's URDF frame, in the model frame
    joints, children = [], {}
    for joint in model.joints:
        if joint['parent'] == 'world':
            if joint['type'] != 'fixed':
                raise SdfError('%s: only a fixed joint can hold a model to the world'
                               % joint['where'])
            model.fixed_to_world = True
            continue
        for end in ('parent', 'child'):
            if joint[end] not in model.links:
                raise SdfError('%s: no link %r in model %s' % (joint['where'], joint[end],
                                                               model.name))
        if joint['child'] in children or joint['child'] == root.name:
            raise SdfError('%s: link %r already has a parent; a model must be a tree'
                           % (joint['where'], joint['child']))
        children[joint['child']] = joint
    _check_masses(model, root, children)
    for link in links[1:]:      # a link without a joint is fixed to the root, where it is
        children.setdefault(link.name, {'name': 'fixed_' + link.name, 'type': 'fixed',
                                        'parent': root.name, 'child': link.name,
                                        'pose': np.eye(4), 'axis': (1, 0, 0),
                                        'in_model_frame': False, 'limit': {}, 'where': ''})
    pending = dict(children)
    while pending:
        ready = [j for j in pending.values() if j['parent'] in frames]
        if not ready:
            raise SdfError('model %s: joints form a loop or miss the root link %r: %s'
                           % (model.name, root.name, ', '.join(sorted(pending))))
        for joint in ready:
            child = model.links[joint['child']]
            frames[child.name] = child.pose.dot(joint['pose'])
            joints.append(joint)
            del pending[joint['child']]
    robot = ET.Element('robot', name=model.name)
    for link in links:
        _write_link(robot, link, np.linalg.inv(frames[link.name]).dot(link.pose))
    for joint in joints:
        _write_joint(robot, joint, frames)
    if model.static or model.fixed_to_world:
        ET.SubElement(ET.SubElement(robot, 'gazebo'), 'static').text = 'true'
    if not model.auto_disable:
        ET.SubElement(ET.SubElement(robot, 'gazebo'), 'allow_auto_disable').text = 'false'
    for plugin in model.plugins:
        ET.SubElement(robot, 'gazebo').append(copy.deepcopy(plugin))
    for link in links:
        _write_gazebo_link(robot, link, np.linalg.inv(frames[link.name]).dot(link.pose))
    ET.indent(robot)
    return ET.tostring(robot, encoding='unicode') + '\n'


def _check_masses(model, root, joints):
    """Inertials as Gazebo 11 uses them. A static model's are never used (ODE
    makes no body for a static link), so they are not checked: one of mass 0
    gets SDF's defaults. A dynamic link of mass 0 is refused by ODE
    (``ODELink::UpdateMass``: 'Setting custom link ... mass to zero!'), while
    sdformat's URDF reader lumps a massless link on a fixed joint into its
    parent: such a link is kept where it is, adding no mass, with one warning;
    one that moves on its own (the root, a moving joint) is refused."""
    for link in model.links.values():
        if link.inertial[0] > 0:
            continue
        if model.static or model.fixed_to_world:
            link.inertial = (1.0, np.eye(4), (1.0, 0.0, 0.0, 1.0, 0.0, 1.0))
            continue
        joint = joints.get(link.name)
        if link is root or (joint is not None and joint['type'] != 'fixed'):
            how = 'the root link' if link is root else 'on %s joint %s' % (joint['type'],
                                                                          joint['name'])
            raise SdfError('%s/inertial/mass: 0 on a dynamic link (%s): Gazebo refuses it too '
                           "(ODE: 'Setting custom link mass to zero!'); give it a mass, or make "
                           'the model static' % (link.where, how))
        parent = joint['parent'] if joint is not None else root.name
        link.inertial = (0.0, np.eye(4), (0.0,) * 6)
        model.warnings.append('%s: mass 0 on a dynamic link: it moves with link %s as if '
                              'lumped into it (Gazebo\'s fixed-joint reduction), adding no mass'
                              % (link.where, parent))


def _num(value):
    return '%.9g' % (float(value) + 0.0)


def _origin(parent, m):
    x, y, z, roll, pitch, yaw = pose_tuple(m)
    ET.SubElement(parent, 'origin', xyz=' '.join(_num(v) for v in (x, y, z)),
                  rpy=' '.join(_num(v) for v in (roll, pitch, yaw)))


def _shape(parent, shape):
    kind, params = shape
    geometry = ET.SubElement(parent, 'geometry')
    if kind == 'box':
        ET.SubElement(geometry, 'box', size=' '.join(_num(v) for v in params['size']))
    elif kind == 'cylinder':
        ET.SubElement(geometry, 'cylinder', radius=_num(params['radius']),
                      length=_num(params['length']))
    elif kind == 'sphere':
        ET.SubElement(geometry, 'sphere', radius=_num(params['radius']))
    else:
        ET.SubElement(geometry, 'mesh', filename=params['filename'],
                      scale=' '.join(_num(v) for v in params['scale']))


def _write_link(robot, link, to_urdf):
    out = ET.SubElement(robot, 'link', name=link.name)
    mass, origin, inertia = link.inertial
    inertial = ET.SubElement(out, 'inertial')
    _origin(inertial, to_urdf.dot(origin))
    ET.SubElement(inertial, 'mass', value=_num(mass))
    ET.SubElement(inertial, 'inertia', **{k: _num(v) for k, v in zip(
        ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz'), inertia)})
    for index, (name, pose, shape, rgba) in enumerate(link.visuals):
        visual = ET.SubElement(out, 'visual', name=name)
        _origin(visual, to_urdf.dot(pose))
        _shape(visual, shape)
        material = ET.SubElement(visual, 'material', name='%s_%s_%d' % (link.name, name, index))
        ET.SubElement(material, 'color', rgba=' '.join(_num(v) for v in rgba))
    for name, pose, shape, _ in link.collisions:
        collision = ET.SubElement(out, 'collision', name=name)
        _origin(collision, to_urdf.dot(pose))
        _shape(collision, shape)


def _write_joint(robot, joint, frames):
    kind, limit = joint['type'], joint['limit']
    lower, upper = limit.get('lower', -NO_LIMIT * 10), limit.get('upper', NO_LIMIT * 10)
    if kind == 'revolute' and lower <= -NO_LIMIT and upper >= NO_LIMIT:
        kind = 'continuous'
    out = ET.SubElement(robot, 'joint', name=joint['name'], type=kind)
    ET.SubElement(out, 'parent', link=joint['parent'])
    ET.SubElement(out, 'child', link=joint['child'])
    _origin(out, np.linalg.inv(frames[joint['parent']]).dot(frames[joint['child']]))
    if kind == 'fixed':
        return
    axis = np.asarray(joint['axis'], float)
    if joint['in_model_frame']:
        axis = frames[joint['child']][:3, :3].T.dot(axis)
    ET.SubElement(out, 'axis', xyz=' '.join(_num(v) for v in axis))
    effort = limit.get('effort', -1)
    velocity = limit.get('velocity', -1)
    attrs = {'effort': _num(effort if effort >= 0 else DEFAULT_EFFORT),
             'velocity': _num(velocity if velocity >= 0 else DEFAULT_VELOCITY)}
    if kind != 'continuous':
        attrs.update(lower=_num(max(lower, -NO_LIMIT)), upper=_num(min(upper, NO_LIMIT)))
    ET.SubElement(out, 'limit', **attrs)


def _write_gazebo_link(robot, link, to_urdf):
    if not link.sensors and not link.extras:
        return
    tag = ET.SubElement(robot, 'gazebo', reference=link.name)
    for key, value in link.extras.items():
        ET.SubElement(tag, key).text = value
    for sensor, sensor_pose in link.sensors:
        moved = copy.deepcopy(sensor)
        pose = moved.find('pose')
        if pose is None:
            pose = ET.SubElement(moved, 'pose')
        pose.attrib.clear()
        pose.text = ' '.join(_num(v) for v in pose_tuple(to_urdf.dot(sensor_pose)))
        tag.append(moved)

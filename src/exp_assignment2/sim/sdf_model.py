"""One SDF ``<model>`` read into plain data (plain Python: no ROS, no pybullet).

:func:`read_model` reads a model (links with their poses, inertials, visuals and
collisions; joints; plugins), flattening nested models and includes into
``nested::link`` names; :func:`~exp_assignment2.sim.sdf_to_urdf.model_urdf`
writes it as URDF text.
"""
import copy
from collections import OrderedDict

import numpy as np

from exp_assignment2.sim.sdf_geometry import (DEFAULT_RGBA, SdfError, child_floats, colour_of,
                                              declared_box, floats, pose_of, shapes_of)

JOINT_TYPES = ('revolute', 'continuous', 'prismatic', 'fixed')
# SDF joints Gazebo moves and a URDF cannot say: held fixed here, one warning each
HELD_FIXED = ('ball', 'universal', 'revolute2', 'screw', 'gearbox')
NO_LIMIT = 1e15             # SDF's default limits are +-1e16: no limit
DEFAULT_EFFORT, DEFAULT_VELOCITY = 1000.0, 100.0    # where SDF gives none (it says -1)


class Model(object):
    """A model as plain data: ``links`` (name -> Link, the first is the root),
    ``joints``, ``plugins`` (elements), ``static``, ``auto_disable`` (SDF's
    ``allow_auto_disable``) and ``pose`` (4x4, in the parent's frame)."""

    def __init__(self, name, pose, static, auto_disable=True):
        self.name, self.pose, self.static = name, pose, static
        self.auto_disable = auto_disable
        self.links, self.joints, self.plugins, self.fixed_to_world = OrderedDict(), [], [], False
        self.warnings = []      # what model_urdf changed, one line each


class Link(object):
    """A link: ``pose`` (4x4, model frame), ``inertial`` (mass, 4x4 origin,
    6 inertia values), ``visuals`` [(name, 4x4, shape, rgba)], ``collisions``
    [(name, 4x4, shape)], ``sensors`` (elements), ``extras`` (gazebo tags)."""

    def __init__(self, name, pose, where=''):
        self.name, self.pose, self.where = name, pose, where or 'link[%s]' % name
        self.inertial = (1.0, np.eye(4), (1.0, 0.0, 0.0, 1.0, 0.0, 1.0))   # SDF's defaults
        self.visuals, self.collisions, self.sensors, self.extras = [], [], [], {}


def flag(elem, tag, default=False):
    """An SDF boolean child (``1``/``true``)."""
    text = elem.findtext(tag)
    return default if text is None else text.strip().lower() in ('1', 'true')


def read_model(elem, where, context):
    """A ``<model>`` element as a :class:`Model`; ``where`` names it in errors."""
    name = elem.get('name') or ''
    if not name:
        raise SdfError('%s: a model needs a name' % where)
    model = Model(name, pose_of(elem, where), flag(elem, 'static'),
                  flag(elem, 'allow_auto_disable', default=True))
    for child in elem:
        if child.tag == 'link':
            link = _read_link(child, '%s/link[%s]' % (where, child.get('name', '')), context)
            if link.name in model.links:
                raise SdfError('%s: two links are called %r' % (where, link.name))
            model.links[link.name] = link
        elif child.tag == 'joint':
            joint = _read_joint(child, '%s/joint[%s]' % (where, child.get('name', '')))
            if joint['type'] in HELD_FIXED:
                model.warnings.append('%s: a %s joint, which Gazebo moves, is held fixed here'
                                      % (joint['where'], joint['type']))
                joint['type'] = 'fixed'
            model.joints.append(joint)
        elif child.tag == 'plugin':
            model.plugins.append(child)
        elif child.tag in ('model', 'include'):
            nested = (read_model(child, '%s/model[%s]' % (where, child.get('name', '')), context)
                      if child.tag == 'model' else context.include(child, where))
            if nested is not None:
                _merge(model, nested)
    return model        # without a link it is Gazebo's empty model: the caller decides


def _merge(model, nested):
    prefix = nested.name + '::'
    for link in nested.links.values():
        moved = copy.copy(link)
        moved.name, moved.pose = prefix + link.name, nested.pose.dot(link.pose)
        model.links[moved.name] = moved
    for joint in nested.joints:
        model.joints.append(dict(joint, name=prefix + joint['name'],
                                 parent=_scoped(prefix, joint['parent']),
                                 child=prefix + joint['child']))
    model.plugins.extend(nested.plugins)


def _scoped(prefix, link):
    return link if link == 'world' else prefix + link


def _read_link(elem, where, context):
    if not elem.get('name'):
        raise SdfError('%s: a link needs a name' % where)
    link = Link(elem.get('name'), pose_of(elem, where), where)
    inertial = elem.find('inertial')
    if inertial is not None:
        w = where + '/inertial'
        mass = child_floats(inertial, 'mass', 1, w, (1.0,))[0]
        # 0 is judged by model_urdf, once the model is known to be static or not
        if mass < 0:
            raise SdfError('%s/mass: must not be negative, not %g' % (w, mass))
        block = inertial.find('inertia')
        values = link.inertial[2]
        if block is not None:
            values = tuple(child_floats(block, tag, 1, w + '/inertia', (default,))[0]
                           for tag, default in zip(('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz'),
                                                   values))
        link.inertial = (mass, pose_of(inertial, w), values)
    found = []      # the link's declared size, read only for a mesh that needs it

    def declared(pose):
        if not found:
            found.append(declared_box(elem, where, context))
        return found[0] and (np.linalg.inv(pose).dot(found[0][0]), found[0][1])
    for kind, out in (('visual', link.visuals), ('collision', link.collisions)):
        for part in elem.findall(kind):
            w = '%s/%s[%s]' % (where, kind, part.get('name', ''))
            pose = pose_of(part, w)
            coloured = kind == 'visual' and part.find('material') is not None
            for offset, shape, own in shapes_of(part, w, context, kind,
                                                lambda pose=pose: declared(pose)):
                rgba = colour_of(part, w) if coloured else own or DEFAULT_RGBA
                out.append((part.get('name', kind), pose.dot(offset), shape, rgba))
    link.sensors = [(sensor, pose_of(sensor, '%s/sensor[%s]' % (where, sensor.get('name', ''))))
                    for sensor in elem.findall('sensor')]
    for tag, default in (('gravity', True), ('kinematic', False)):
        if elem.find(tag) is not None and flag(elem, tag) != default:
            link.extras[tag] = 'true' if not default else 'false'
    return link


def _read_joint(elem, where):
    kind = elem.get('type', '')
    if kind not in JOINT_TYPES + HELD_FIXED:
        raise SdfError('%s: joint type %r is not an SDF joint type; accepted: %s'
                       % (where, kind, ', '.join(JOINT_TYPES + HELD_FIXED)))
    parent, child = elem.findtext('parent', '').strip(), elem.findtext('child', '').strip()
    if not parent or not child:
        raise SdfError('%s: a joint needs a <parent> and a <child>' % where)
    joint = {'name': elem.get('name') or child, 'type': kind, 'parent': parent,
             'child': child, 'pose': pose_of(elem, where), 'where': where,
             'axis': (1.0, 0.0, 0.0), 'in_model_frame': False, 'limit': {}}
    axis = elem.find('axis')
    if axis is not None:
        xyz = axis.find('xyz')
        if xyz is not None:
            joint['axis'] = tuple(floats(xyz.text, 3, where + '/axis/xyz', 'an axis'))
            joint['in_model_frame'] = xyz.get('expressed_in') == '__model__'
        joint['in_model_frame'] |= flag(axis, 'use_parent_model_frame')
        limit = axis.find('limit')
        if limit is not None:
            for tag in ('lower', 'upper', 'effort', 'velocity'):
                if limit.find(tag) is not None:
                    joint['limit'][tag] = child_floats(limit, tag, 1, where + '/axis/limit')[0]
    return joint

"""Poses, shapes and colours of SDF elements, as plain data (no ROS, no pybullet).

Helpers of :mod:`.sdf_model`: an SDF ``<pose>`` as a 4x4 matrix, a
``<geometry>`` as the URDF shapes that stand for it (box, cylinder, sphere,
mesh file), a ``<material>`` as an RGBA colour. Every error is an
:class:`SdfError` that names the element it is about.
"""
import math
import os

import numpy as np

from exp_assignment2.sim.gazebo_materials import GAZEBO_MATERIALS, UNKNOWN
from exp_assignment2.sim.rotations import rpy_matrix

PLANE_THICKNESS = 0.02      # a <plane> becomes a box this thick whose top face is the plane
DEFAULT_RGBA = (0.7, 0.7, 0.7, 1.0)     # a visual with no material: light grey
MESH_FILE_TYPES = ('.stl', '.obj')      # what the simulator can load; others need a stand-in


class SdfError(ValueError):
    """An SDF document that cannot be read; the message names the element."""


def floats(text, count, where, what):
    """``count`` finite numbers from an element's text, or an SdfError."""
    parts = (text or '').split()
    try:
        values = [float(p) for p in parts]
    except ValueError:
        values = None
    if values is None or len(values) != count or not all(math.isfinite(v) for v in values):
        raise SdfError('%s: %s must be %d finite numbers, not %r'
                       % (where, what, count, (text or '').strip()))
    return values


def child_floats(elem, tag, count, where, default=None):
    """The numbers of ``elem``'s child ``tag``; ``default`` when it is absent."""
    found = elem.find(tag)
    if found is None:
        if default is None:
            raise SdfError('%s: <%s> is missing' % (where, tag))
        return list(default)
    return floats(found.text, count, '%s/%s' % (where, tag), 'the value')


def pose_of(elem, where):
    """4x4 transform of ``elem``'s ``<pose>`` (identity when absent), in the
    frame of the parent element, which is the only frame this reader knows."""
    pose = elem.find('pose')
    if pose is None:
        return np.eye(4)
    frame = pose.get('relative_to', pose.get('frame', ''))
    if frame:
        raise SdfError('%s/pose: a pose relative to frame %r is not supported; '
                       'give it in the parent element\'s frame' % (where, frame))
    if pose.get('rotation_format', 'euler_rpy') != 'euler_rpy':
        raise SdfError('%s/pose: rotation_format %r is not supported; use euler_rpy'
                       % (where, pose.get('rotation_format')))
    values = floats(pose.text, 6, where + '/pose', 'a pose')
    if pose.get('degrees', 'false') in ('true', '1'):
        values[3:] = [math.radians(v) for v in values[3:]]
    return transform(values[:3], values[3:])


def transform(xyz, rpy):
    """4x4 transform of a translation and URDF roll/pitch/yaw."""
    m = np.eye(4)
    m[:3, :3] = rpy_matrix(*rpy)
    m[:3, 3] = xyz
    return m


def matrix_rpy(m):
    """(roll, pitch, yaw) of a rotation, URDF's convention (Rz Ry Rx)."""
    r = np.asarray(m)[:3, :3]
    pitch = math.atan2(-r[2, 0], math.hypot(r[0, 0], r[1, 0]))
    if abs(math.cos(pitch)) < 1e-9:     # gimbal lock: put all the yaw in roll
        return math.atan2(-r[1, 2], r[1, 1]), pitch, 0.0
    return math.atan2(r[2, 1], r[2, 2]), pitch, math.atan2(r[1, 0], r[0, 0])


def pose_tuple(m):
    """(x, y, z, roll, pitch, yaw) of a 4x4 transform."""
    return tuple(float(v) for v in m[:3, 3]) + tuple(float(v) for v in matrix_rpy(m))


def colour_of(visual, where):
    """RGBA of a ``<visual>``'s ``<material>``: diffuse, else ambient, else a
    Gazebo script name, else a light grey."""
    material = visual.find('material')
    if material is None:
        return DEFAULT_RGBA
    for tag in ('diffuse', 'ambient'):
        found = material.find(tag)
        if found is not None and found.text and found.text.strip():
            n = len(found.text.split())
            rgba = floats(found.text, 4 if n == 4 else 3, '%s/material/%s' % (where, tag),
                          'a colour')
            return tuple(min(max(v, 0.0), 1.0) for v in rgba + [1.0][:4 - len(rgba)])
    name = material.findtext('script/name', '').strip()
    return GAZEBO_MATERIALS.get(name, UNKNOWN)


PRIMITIVES = ('box', 'cylinder', 'sphere')


def declared_box(link, where, context):
    """The size a link declares for its shapes, as Gazebo models give it next
    to a mesh: (4x4 centre, [x, y, z] size) in the link frame of the box that
    bounds its box, cylinder and sphere collisions, or None without any."""
    corners = []
    for part in link.findall('collision'):
        geometry = part.find('geometry')
        if geometry is None or len(geometry) == 0 or geometry[0].tag not in PRIMITIVES:
            continue
        w = '%s/collision[%s]' % (where, part.get('name', ''))
        pose = pose_of(part, w)
        for offset, (kind, params), _ in shapes_of(part, w, context, 'collision'):
            half = (np.asarray(params['size']) / 2.0 if kind == 'box' else
                    np.array([params['radius']] * 2 + [params['length'] / 2.0])
                    if kind == 'cylinder' else np.array([params['radius']] * 3))
            frame = pose.dot(offset)
            for sign in np.array(np.meshgrid([-1, 1], [-1, 1], [-1, 1])).T.reshape(-1, 3):
                corners.append(frame[:3, :3].dot(sign * half) + frame[:3, 3])
    if not corners:
        return None
    low, high = np.min(corners, axis=0), np.max(corners, axis=0)
    centre = np.eye(4)
    centre[:3, 3] = (low + high) / 2.0
    return centre, [float(v) for v in high - low]


# SDF shapes Gazebo builds and the simulator does not
UNDRAWN = ('heightmap', 'polyline', 'image')


def shapes_of(geometry_parent, where, context, part='visual', declared=None):
    """The ``<geometry>`` of a visual or collision (``part``) as [(4x4 offset,
    (kind, params), rgba)]: what URDF shapes stand for it, placed in the
    element's frame; rgba is a stand-in's own colour, else None. ``declared()``
    (:func:`declared_box` in the element's frame, or None) sizes the box that
    stands in for a visual's mesh of a model nobody knows the size of."""
    geometry = geometry_parent.find('geometry')
    where += '/geometry'
    if geometry is None or len(geometry) == 0:
        raise SdfError('%s: no shape' % where)
    shape = geometry[0]
    kind = shape.tag
    if kind == 'empty':
        return []
    if kind == 'box':
        size = child_floats(shape, 'size', 3, where + '/box', (1, 1, 1))
        return [(np.eye(4), ('box', {'size': _positive(size, where + '/box/size')}), None)]
    if kind == 'cylinder':
        radius = child_floats(shape, 'radius', 1, where + '/cylinder', (0.5,))[0]
        length = child_floats(shape, 'length', 1, where + '/cylinder', (1,))[0]
        _positive([radius, length], where + '/cylinder')
        return [(np.eye(4), ('cylinder', {'radius': radius, 'length': length}), None)]
    if kind == 'sphere':
        radius = child_floats(shape, 'radius', 1, where + '/sphere', (0.5,))[0]
        return [(np.eye(4), ('sphere', {'radius': _positive([radius], where + '/sphere')[0]}),
                 None)]
    if kind == 'plane':
        return [_plane(shape, where + '/plane')]
    if kind == 'mesh':
        return _mesh(shape, where + '/mesh', context, part, declared)
    if kind in UNDRAWN:     # Gazebo builds them; here the element is left out, said once
        context.left_out('%s: a <%s> is not simulated here: left out' % (where, kind))
        return []
    raise SdfError('%s: unknown shape <%s>; accepted: box, cylinder, sphere, plane, mesh'
                   % (where, kind))


def _positive(values, where):
    if any(v <= 0 for v in values):
        raise SdfError('%s: sizes must be positive, not %s' % (where, ' '.join(
            '%g' % v for v in values)))
    return values


def _plane(shape, where):
    normal = np.array(child_floats(shape, 'normal', 3, where, (0, 0, 1)))
    size = child_floats(shape, 'size', 2, where, (100, 100))
    length = np.linalg.norm(normal)
    if length < 1e-9:
        raise SdfError('%s/normal: a normal cannot be zero' % where)
    normal = normal / length
    # rotate +z onto the normal, then sink the box by half its thickness
    axis = np.cross((0, 0, 1), normal)
    angle = math.atan2(np.linalg.norm(axis), normal[2])
    offset = np.eye(4)
    if np.linalg.norm(axis) > 1e-9:
        offset[:3, :3] = _axis_angle(axis / np.linalg.norm(axis), angle)
    elif normal[2] < 0:
        offset[:3, :3] = np.diag((1.0, -1.0, -1.0))
    offset[:3, 3] = -normal * PLANE_THICKNESS / 2
    return offset, ('box', {'size': _positive(size, where + '/size') + [PLANE_THICKNESS]}), None


def _axis_angle(axis, angle):
    x, y, z = axis
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k.dot(k)


def _mesh(shape, where, context, part, declared):
    uri = shape.findtext('uri', '').strip()
    if not uri:
        raise SdfError('%s: no <uri>' % where)
    scale = child_floats(shape, 'scale', 3, where, (1, 1, 1))
    path = context.mesh_file(uri)
    if path is not None and os.path.splitext(path)[1].lower() in MESH_FILE_TYPES:
        return [(np.eye(4), ('mesh', {'filename': path, 'scale': scale}), None)]
    box = (declared() if declared is not None and part == 'visual' and not context.knows(uri)
           else None)
    stand_in = context.stand_in(uri, where, installed=path is not None,
                                declared=box[1] if box else None)
    if stand_in.get('declared'):    # sized by the link's own collisions, in metres
        return [(box[0], ('box', {'size': _positive(list(stand_in['size']), where)}),
                 stand_in['rgba'])]
    if stand_in.get('default') and part == 'collision':
        return []       # a guessed box must not stop a robot where the real mesh would not
    offset = np.eye(4)
    offset[:3, 3] = [c * s for c, s in zip(stand_in['center'], scale)]
    size = [abs(v * s) for v, s in zip(stand_in['size'], scale)]
    return [(offset, ('box', {'size': _positive(size, where + '/scale')}), stand_in['rgba'])]

"""URDF visuals and frames as plain data, for the GL renderer.

Plain Python + numpy (no pybullet, no GL): :func:`parse_urdf` reads a URDF's
links, joints and ``<visual>`` elements (origin, box / cylinder / sphere /
capsule / OBJ or STL mesh with ``scale``, material colour by inline
``<color>`` or by name); :func:`resolve_mesh_path` finds a mesh file. Also the
pose helpers both halves of the renderer use. :mod:`.gl_meshes` turns the
parsed visuals into triangles.
"""
import logging
import math
import os
import xml.etree.ElementTree as ET
from collections import namedtuple

import numpy as np

log = logging.getLogger(__name__)

DEFAULT_RGBA = (1.0, 1.0, 1.0, 1.0)   # pybullet's colour for a visual without material

Visual = namedtuple('Visual', 'origin kind params rgba')
Visual.__doc__ = """One ``<visual>``: 4x4 origin in the link frame, geometry kind
('box', 'cylinder', 'sphere', 'mesh'), its parameters (dict) and RGBA colour."""
Joint = namedtuple('Joint', 'name parent child origin type')
Joint.__doc__ = """A URDF joint: parent/child link names, 4x4 origin, type."""
UrdfModel = namedtuple('UrdfModel', 'name root visuals joints')
UrdfModel.__doc__ = """A parsed URDF: robot name, root link name, visuals
(dict link name -> list of :class:`Visual`, every link present) and joints."""


def rpy_matrix(roll, pitch, yaw):
    """3x3 rotation of URDF fixed-axis roll/pitch/yaw: Rz(yaw) Ry(pitch) Rx(roll)."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch),
                              math.sin(pitch), math.cos(yaw), math.sin(yaw))
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def quaternion_matrices(q):
    """(n, 3, 3) rotations of (n, 4) unit (x, y, z, w) quaternions, vectorised."""
    x, y, z, w = np.asarray(q, float).reshape(-1, 4).T
    return np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                     2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                     2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
                    -1).reshape(-1, 3, 3)


def pose_matrix(position, orientation):
    """4x4 pose from a position and an (x, y, z, w) quaternion or a 3x3 rotation."""
    m, o = np.eye(4), np.asarray(orientation, float)
    m[:3, :3] = o if o.shape == (3, 3) else quaternion_matrices(o)[0]
    m[:3, 3] = position
    return m


def _floats(text, n, default):
    if text is None:
        return tuple(default)
    values = [float(v) for v in text.split()]
    if len(values) != n:
        raise ValueError('expected %d numbers, got %r' % (n, text))
    return tuple(values)


def _origin(elem):
    """4x4 transform of an element's ``<origin xyz rpy>`` (identity if absent)."""
    m = np.eye(4)
    o = elem.find('origin') if elem is not None else None
    if o is not None:
        m[:3, :3] = rpy_matrix(*_floats(o.get('rpy'), 3, (0, 0, 0)))
        m[:3, 3] = _floats(o.get('xyz'), 3, (0, 0, 0))
    return m


def resolve_mesh_path(filename, urdf_dir):
    """A mesh's file path: ``package://name/rest`` is looked up on
    ROS_PACKAGE_PATH and among the URDF's ancestor directories called ``name``
    (or any ancestor holding ``rest``); plain paths are relative to the URDF."""
    if filename.startswith('file://'):
        filename = filename[len('file://'):]
    if not filename.startswith('package://'):
        return filename if os.path.isabs(filename) else os.path.join(urdf_dir, filename)
    pkg, _, rest = filename[len('package://'):].partition('/')
    candidates = [os.path.join(root, pkg, rest)
                  for root in os.environ.get('ROS_PACKAGE_PATH', '').split(os.pathsep) if root]
    d = os.path.abspath(urdf_dir)
    while True:
        if os.path.basename(d) == pkg:
            candidates.insert(0, os.path.join(d, rest))
        candidates.append(os.path.join(d, rest))
        parent = os.path.dirname(d)
        if parent == d:
            break
        d = parent
    for c in candidates:
        if os.path.exists(c):
            return c
    return candidates[0]


def parse_urdf(path):
    """Parse a URDF file into a :class:`UrdfModel` (visual geometry only)."""
    root = ET.parse(path).getroot()
    urdf_dir = os.path.dirname(os.path.abspath(path))
    # Materials may be defined at top level or inline in a visual and then
    # referenced by name elsewhere; top-level ones take precedence.
    materials = {}
    for m in root.findall('material'):
        c = m.find('color')
        if c is not None:
            materials[m.get('name')] = _floats(c.get('rgba'), 4, DEFAULT_RGBA)
    for m in root.iter('material'):
        c = m.find('color')
        if c is not None and m.get('name') and m.get('name') not in materials:
            materials[m.get('name')] = _floats(c.get('rgba'), 4, DEFAULT_RGBA)
    visuals = {}
    for link in root.findall('link'):
        out = visuals.setdefault(link.get('name'), [])
        for v in link.findall('visual'):
            geom = v.find('geometry')
            shape = geom[0] if geom is not None and len(geom) else None
            if shape is None:
                continue
            mat = v.find('material')
            rgba = DEFAULT_RGBA
            if mat is not None:
                c = mat.find('color')
                rgba = (_floats(c.get('rgba'), 4, DEFAULT_RGBA) if c is not None
                        else materials.get(mat.get('name'), DEFAULT_RGBA))
            kind, a = shape.tag, shape.attrib
            if kind == 'box':
                params = {'size': _floats(a.get('size'), 3, (1, 1, 1))}
            elif kind in ('cylinder', 'capsule'):
                params = {'radius': float(a['radius']), 'length': float(a['length'])}
            elif kind == 'sphere':
                params = {'radius': float(a['radius'])}
            elif kind == 'mesh':
                params = {'filename': resolve_mesh_path(a['filename'], urdf_dir),
                          'scale': _floats(a.get('scale'), 3, (1, 1, 1))}
            else:
                log.warning('%s: link %s: unsupported geometry <%s>, not drawn',
                            path, link.get('name'), kind)
                continue
            out.append(Visual(_origin(v), kind, params, tuple(rgba)))
    joints = [Joint(j.get('name'), j.find('parent').get('link'), j.find('child').get('link'),
                    _origin(j), j.get('type')) for j in root.findall('joint')]
    children = {j.child for j in joints}
    roots = [name for name in visuals if name not in children]
    return UrdfModel(root.get('name'), roots[0] if roots else None, visuals, joints)

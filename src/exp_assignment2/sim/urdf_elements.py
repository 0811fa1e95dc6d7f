"""The elements of a URDF read one by one (no ROS, no pybullet, no GL): a link's
visuals and collisions with their geometry and colour, its mass, a joint, the
named materials, an ``<origin>``; mesh paths resolved. :func:`~.urdf.parse`
puts them together into a model."""
import math
import os
from collections import namedtuple

import numpy as np

from exp_assignment2.sim.rotations import rpy_matrix

DEFAULT_RGBA = (1.0, 1.0, 1.0, 1.0)   # pybullet's colour for a visual without material
# The largest size (m) and mesh scale a shape may have: Gazebo's ground plane
# is 100 m, and pybullet's collision detection cannot hold a 1e30 m box (every
# body near it was thrown out of the world)
MAX_EXTENT = 1.0e4

Visual = namedtuple('Visual', 'origin kind params rgba')
Visual.__doc__ = """One ``<visual>`` (or ``<collision>``): 4x4 origin in the link frame,
geometry kind ('box', 'cylinder', 'sphere', 'capsule', 'mesh'), its parameters
(dict: size / radius, length / filename, scale) and RGBA colour."""
Link = namedtuple('Link', 'name visuals collisions mass')
Joint = namedtuple('Joint', 'name type parent child origin axis lower upper effort velocity')
Joint.__doc__ = """A URDF joint: 4x4 origin in the parent link's frame, unit axis in the
joint frame, limits (lower/upper None for continuous joints)."""


class UrdfError(ValueError):
    """A URDF that cannot be read, with the reason."""


def floats(text, n, default, where='value'):
    """``n`` numbers from a space-separated attribute, or ``default`` when absent."""
    if text is None:
        return tuple(default)
    try:
        values = [float(v) for v in text.split()]
    except ValueError:
        raise UrdfError('%s: %r is not %d numbers' % (where, text, n))
    if len(values) != n or not all(math.isfinite(v) for v in values):
        raise UrdfError('%s: expected %d finite numbers, got %r' % (where, n, text))
    return tuple(values)


def origin_matrix(elem, where='origin'):
    """4x4 transform of an element's ``<origin xyz rpy>`` (identity if absent)."""
    m = np.eye(4)
    o = elem.find('origin') if elem is not None else None
    if o is not None:
        m[:3, :3] = rpy_matrix(*floats(o.get('rpy'), 3, (0, 0, 0), where + ' rpy'))
        m[:3, 3] = floats(o.get('xyz'), 3, (0, 0, 0), where + ' xyz')
    return m


def resolve_mesh_path(filename, base_dir):
    """A mesh's file path: ``package://name/rest`` is looked up on
    ROS_PACKAGE_PATH and among ``base_dir``'s ancestors called ``name`` (or any
    ancestor holding ``rest``); plain paths are relative to ``base_dir``."""
    if filename.startswith('file://'):
        filename = filename[len('file://'):]
    if not filename.startswith('package://'):
        return filename if os.path.isabs(filename) else os.path.join(base_dir, filename)
    pkg, _, rest = filename[len('package://'):].partition('/')
    candidates = [os.path.join(root, pkg, rest)
                  for root in os.environ.get('ROS_PACKAGE_PATH', '').split(os.pathsep) if root]
    d = os.path.abspath(base_dir)
    while True:
        if os.path.basename(d) == pkg:
            candidates.insert(0, os.path.join(d, rest))
        candidates.append(os.path.join(d, rest))
        parent = os.path.dirname(d)
        if parent == d:
            break
        d = parent
    return next((c for c in candidates if os.path.exists(c)), candidates[0])


def geometry(elem, where, base_dir):
    geom = elem.find('geometry')
    shape = geom[0] if geom is not None and len(geom) else None
    if shape is None:
        raise UrdfError('%s: no geometry' % where)
    kind, a = shape.tag, shape.attrib
    try:
        if kind == 'box':
            size = floats(a.get('size'), 3, (1, 1, 1), where + ' box size')
            return kind, {'size': extents(size, where, kind, 'size')}
        if kind in ('cylinder', 'capsule'):
            return kind, {'radius': extents([float(a['radius'])], where, kind, 'radius')[0],
                          'length': extents([float(a['length'])], where, kind, 'length')[0]}
        if kind == 'sphere':
            return kind, {'radius': extents([float(a['radius'])], where, kind, 'radius')[0]}
        if kind == 'mesh':
            scale = floats(a.get('scale'), 3, (1, 1, 1), where + ' scale')
            extents([abs(s) for s in scale], where, kind, 'scale')
            return kind, {'filename': resolve_mesh_path(a['filename'], base_dir),
                          'scale': scale}
    except UrdfError:
        raise           # already says where
    except (KeyError, ValueError) as exc:
        raise UrdfError('%s: <%s> %s' % (where, kind, exc))
    return kind, {}    # an unknown shape: kept, not drawn (the renderer says so)


def extents(values, where, kind, name):
    """``values`` if each is a size pybullet can hold: finite, in [0, MAX_EXTENT]."""
    if not all(math.isfinite(v) and 0.0 <= v <= MAX_EXTENT for v in values):
        raise UrdfError('%s: <%s> %s %s: each must be in [0, %g]'
                        % (where, kind, name, ' '.join('%.10g' % v for v in values),
                           MAX_EXTENT))
    return tuple(values)


def materials(root, where):
    """Named materials: top level first, then any named inline one."""
    materials = {}
    for level in (root.findall('material'), root.iter('material')):
        for m in level:
            c = m.find('color')
            if c is not None and m.get('name') and m.get('name') not in materials:
                materials[m.get('name')] = floats(c.get('rgba'), 4, DEFAULT_RGBA,
                                                  '%s material %s' % (where, m.get('name')))
    return materials


def link(elem, materials, gazebo_colour, base_dir):
    name = elem.get('name')
    visuals, collisions = [], []
    for kind, out in (('visual', visuals), ('collision', collisions)):
        for v in elem.findall(kind):
            where = 'link %s %s' % (name, kind)
            shape, params = geometry(v, where, base_dir)
            rgba = DEFAULT_RGBA
            mat = v.find('material')
            if mat is not None:
                c = mat.find('color')
                rgba = (floats(c.get('rgba'), 4, DEFAULT_RGBA, where + ' color')
                        if c is not None else materials.get(mat.get('name'), DEFAULT_RGBA))
            if gazebo_colour is not None:
                rgba = gazebo_colour
            out.append(Visual(origin_matrix(v, where), shape, params, tuple(rgba)))
    return Link(name, visuals, collisions, mass(elem.find('inertial'), name))


def mass(inertial, name):
    """A link's mass (0 without an ``<inertial>``); every number of the
    inertial finite (ODE's bodies go NaN otherwise), the mass >= 0."""
    if inertial is None:
        return 0.0
    mass = inertial.find('mass')
    value = floats(mass.get('value', '0'), 1, (0.0,), 'link %s mass' % name)[0] \
        if mass is not None else 0.0
    if value < 0:
        raise UrdfError('link %s: mass %.10g is negative' % (name, value))
    block = inertial.find('inertia')
    for key in ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz'):
        floats(block.get(key) if block is not None else None, 1, (0.0,),
               'link %s inertia %s' % (name, key))
    origin_matrix(inertial, 'link %s inertial origin' % name)
    return value


def joint(elem):
    name, kind = elem.get('name'), elem.get('type')
    where = 'joint %s' % name
    parent, child = elem.find('parent'), elem.find('child')
    if parent is None or child is None or kind is None:
        raise UrdfError('%s: needs a type, a parent and a child' % where)
    axis = np.array(floats(elem.find('axis').get('xyz') if elem.find('axis') is not None
                           else None, 3, (1, 0, 0), where + ' axis'))
    if np.linalg.norm(axis) == 0:
        raise UrdfError('%s: the axis is zero' % where)
    limit = elem.find('limit')
    lower = upper = None
    effort = velocity = float('inf')
    if limit is not None:
        effort = float(limit.get('effort', 'inf'))
        velocity = float(limit.get('velocity', 'inf'))
        if kind in ('revolute', 'prismatic'):
            lower, upper = float(limit.get('lower', 0)), float(limit.get('upper', 0))
    return Joint(name, kind, parent.get('link'), child.get('link'), origin_matrix(elem, where),
                 axis / np.linalg.norm(axis), lower, upper, effort, velocity)

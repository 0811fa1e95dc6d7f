"""The elements of a URDF read one by one, as urdfdom reads them (no ROS, no
pybullet, no GL): a visual's or collision's geometry, a link's mass, a joint,
the named materials, an ``<origin>``; mesh paths resolved. A link's elements
are put together by :mod:`.urdf_links`, the model by :func:`~.urdf.parse`.

urdfdom (the parser of every ROS release, and Gazebo's through sdformat)
refuses a URDF for a joint it cannot read, but only drops a link's element
it cannot read (:mod:`.urdf_links`): a :class:`UrdfError` from a visual or an
inertial is such a drop, a :class:`BreaksTheWorld` is a refusal urdfdom does
not make (pybullet cannot hold the value, or Gazebo's ODE refuses it later)."""
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


class BreaksTheWorld(UrdfError):
    """A value urdfdom reads but that would break the world (a 1e30 m box, a
    negative mass: Gazebo's ODE throws on it): the model is refused."""

# urdfdom's joint types; it reads no axis of the last two (joint.cpp)
MOVING_JOINTS = ('revolute', 'continuous', 'prismatic', 'planar')
AXISLESS_JOINTS = ('fixed', 'floating')


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
    """(kind, params) of an element's ``<geometry>``; UrdfError with
    urdfdom's words when it cannot read it (link.cpp's parseGeometry)."""
    geom = elem.find('geometry')
    if geom is None:
        raise UrdfError('%s: no <geometry>' % where)
    shape = next((c for c in geom if isinstance(c.tag, str)), None)
    if shape is None:
        raise UrdfError('%s: Geometry tag contains no child element.' % where)
    kind, a = shape.tag, shape.attrib
    if kind == 'box':
        if a.get('size') is None:
            raise UrdfError('%s: Box shape has no size attribute' % where)
        size = floats(a.get('size'), 3, (1, 1, 1), where + ' box size')
        return kind, {'size': extents(size, where, kind, 'size')}
    if kind in ('cylinder', 'capsule'):     # capsule: pybullet's, urdfdom drops it
        if a.get('length') is None or a.get('radius') is None:
            raise UrdfError('%s: Cylinder shape must have both length and radius attributes'
                            % where)
        return kind, {'radius': extents([_number(a, 'radius', where)], where, kind, 'radius')[0],
                      'length': extents([_number(a, 'length', where)], where, kind, 'length')[0]}
    if kind == 'sphere':
        if a.get('radius') is None:
            raise UrdfError('%s: Sphere shape must have a radius attribute' % where)
        return kind, {'radius': extents([_number(a, 'radius', where)], where, kind, 'radius')[0]}
    if kind == 'mesh':
        if a.get('filename') is None:
            raise UrdfError('%s: Mesh must contain a filename attribute' % where)
        try:
            scale = floats(a.get('scale'), 3, (1, 1, 1), where + ' scale')
        except UrdfError as exc:
            raise UrdfError('%s: Mesh scale was specified, but could not be parsed (%s)'
                            % (where, exc))
        extents([abs(v) for v in scale], where, kind, 'scale')
        return kind, {'filename': resolve_mesh_path(a['filename'], base_dir), 'scale': scale}
    raise UrdfError("%s: Unknown geometry type '%s'" % (where, kind))


def _number(attrib, name, where):
    try:
        value = float(attrib[name])
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise UrdfError('%s: %s [%s] is not a valid float' % (where, name, attrib[name]))
    return value


def extents(values, where, kind, name):
    """``values`` if each is a size pybullet can hold: finite, in [0, MAX_EXTENT]."""
    if not all(math.isfinite(v) and 0.0 <= v <= MAX_EXTENT for v in values):
        raise BreaksTheWorld('%s: <%s> %s %s: each must be in [0, %g]'
                        % (where, kind, name, ' '.join('%.10g' % v for v in values),
                           MAX_EXTENT))
    return tuple(values)


def materials(root, where):
    """({name: RGBA}, [error lines]): the named materials, top level first,
    then any named inline one. A colour urdfdom cannot read is logged and
    the material left without it, as urdfdom's parseMaterial does."""
    found, lines = {}, []
    for top, level in ((True, root.findall('material')), (False, root.iter('material'))):
        for m in level:
            c = m.find('color')
            if c is None or not m.get('name') or m.get('name') in found:
                continue
            rgba, error = material_colour(m, {}, '%s material %s' % (where, m.get('name')))
            if error and top:       # an inline one is said where its visual is read
                lines.append(error)
            elif rgba is not None:
                found[m.get('name')] = rgba
    return found, lines


def material_colour(mat, materials, where):
    """(RGBA or None, error line or None) of a visual's ``<material>``: its
    inline colour, else the named top-level one. urdfdom logs a bad inline
    colour and goes on without it (link.cpp's parseMaterial)."""
    c = mat.find('color')
    if c is not None and c.get('rgba') is not None:
        try:
            rgba = floats(c.get('rgba'), 4, DEFAULT_RGBA, where + ' color')
            if all(0.0 <= v <= 1.0 for v in rgba):
                return tuple(rgba), None
        except UrdfError:
            pass
        return materials.get(mat.get('name')), (
            '%s: Material [%s] has malformed color rgba values: %r (urdfdom: 4 numbers in '
            '[0, 1]); drawn without it' % (where, mat.get('name'), c.get('rgba')))
    return materials.get(mat.get('name')), None


def mass(inertial, name):
    """A link's mass from its ``<inertial>``, as urdfdom's parseInertial
    reads it: UrdfError (urdfdom's words) for what it cannot read; the mass
    read before an unreadable ``<inertia>`` is kept (``exc.mass``)."""
    where = 'link %s inertial' % name
    try:
        origin_matrix(inertial, where + ' origin')
    except UrdfError as exc:
        raise _with_mass(exc, 0.0)
    element = inertial.find('mass')
    if element is None:
        raise _with_mass(UrdfError('%s: Inertial element must have a mass element' % where), 0.0)
    if element.get('value') is None:
        raise _with_mass(UrdfError('%s: Inertial: mass element must have value attribute'
                                   % where), 0.0)
    try:
        value = floats(element.get('value'), 1, (0.0,))[0]
    except UrdfError:
        raise _with_mass(UrdfError('%s: Inertial: mass [%s] is not a valid double'
                                   % (where, element.get('value'))), 0.0)
    if value < 0:       # urdfdom reads it; Gazebo's ODE throws (ODELink::UpdateMass)
        raise BreaksTheWorld("link %s: mass %.10g is negative (Gazebo's ODE refuses it: "
                             "'Setting custom link ... mass to zero!')" % (name, value))
    block = inertial.find('inertia')
    if block is None:
        raise _with_mass(UrdfError('%s: Inertial element must have inertia element' % where),
                         value)
    for key in ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz'):
        if block.get(key) is None:
            raise _with_mass(UrdfError('%s: Inertial: inertia element missing %s attribute'
                                       % (where, key)), value)
        try:
            floats(block.get(key), 1, (0.0,))
        except UrdfError:
            raise _with_mass(UrdfError('%s: Inertial: inertia element %s is not a valid double'
                                       % (where, key)), value)
    return value


def _with_mass(exc, value):
    exc.mass = value
    return exc


def joint(elem):
    """A :class:`Joint` as urdfdom's parseJoint reads it: no axis for a
    fixed or floating joint; a moving joint's axis as given, even zero
    (``axis`` is then (0, 0, 0): :func:`~.urdf.parse` makes it what Gazebo
    makes of it); UrdfError with urdfdom's words for what it refuses."""
    name, kind = elem.get('name'), elem.get('type')
    where = 'joint %s' % name
    parent, child = elem.find('parent'), elem.find('child')
    if kind is None:
        raise UrdfError("%s: joint [%s] has no type, check to see if it's a reference."
                        % (where, name))
    if kind not in MOVING_JOINTS + AXISLESS_JOINTS:
        raise UrdfError('%s: Joint [%s] has no known type [%s] (urdfdom knows %s)'
                        % (where, name, kind, ', '.join(MOVING_JOINTS + AXISLESS_JOINTS)))
    if parent is None or child is None or not parent.get('link') or not child.get('link'):
        raise UrdfError('%s: Joint [%s] is missing a parent and/or child link specification.'
                        % (where, name))
    origin = origin_matrix(elem, where)
    axis = np.array((1.0, 0.0, 0.0))
    element = elem.find('axis')
    if kind in MOVING_JOINTS and element is not None and element.get('xyz') is not None:
        try:
            axis = np.array(floats(element.get('xyz'), 3, (1, 0, 0), where + ' axis'))
        except UrdfError as exc:
            raise UrdfError('%s: Malformed axis element for joint [%s]: %s' % (where, name, exc))
    norm = np.linalg.norm(axis)
    lower = upper = None
    effort = velocity = float('inf')
    limit = elem.find('limit')
    if limit is not None:
        effort, velocity = (_limit(limit, key, 'inf', where) for key in ('effort', 'velocity'))
        lower, upper = (_limit(limit, key, '0', where) for key in ('lower', 'upper'))
        if kind not in ('revolute', 'prismatic'):
            lower = upper = None
    elif kind == 'revolute':
        raise UrdfError('%s: Joint [%s] is of type REVOLUTE but it does not specify limits'
                        % (where, name))
    elif kind == 'prismatic':
        raise UrdfError('%s: Joint [%s] is of type PRISMATIC without limits' % (where, name))
    return Joint(name, kind, parent.get('link'), child.get('link'), origin,
                 axis / norm if norm > 0 else axis * 0.0, lower, upper, effort, velocity)


def _limit(limit, key, default, where):
    text = limit.get(key, default)
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if math.isnan(value) or (key in ('lower', 'upper') and not math.isfinite(value)):
        raise UrdfError('%s: %s value (%s) is not a valid float' % (where, key, text))
    return value

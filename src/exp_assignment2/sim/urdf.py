"""A URDF read once, for physics and drawing alike (no ROS, no pybullet, no GL).

:func:`parse` turns URDF text into a :class:`UrdfModel`: links with their
visuals, collisions and inertials, joints with origins, axes and limits,
materials resolved to RGBA, mesh paths resolved (``package://``, relative to
the file), and the ``<gazebo>`` extension tags read by
:mod:`exp_assignment2.sim.gazebo_tags` (plugins, sensors, Gazebo colours,
static models). A link coloured by ``<gazebo reference><material>`` is drawn
in that colour, as Gazebo draws it. Links without mass are modeled as
Gazebo 11 models them (:mod:`.urdf_masses`): what Gazebo leaves out is left
out, with one warning line each. :meth:`UrdfModel.bullet_text` is the text
pybullet loads: mesh paths made absolute, nothing else changed.
"""
import math
import os
import xml.etree.ElementTree as ET
from collections import OrderedDict, namedtuple

import numpy as np

from exp_assignment2.sim import gazebo_tags, urdf_masses

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


class UrdfModel(object):
    """A parsed URDF. ``links`` and ``joints`` are ordered dicts by name;
    ``root`` is the root link's name; ``gazebo`` the :class:`~.gazebo_tags.GazeboTags`."""

    def __init__(self, name, root, links, joints, gazebo, tree, base_dir):
        self.name, self.root, self.links, self.joints = name, root, links, joints
        self.gazebo, self._tree, self.base_dir = gazebo, tree, base_dir
        self.warnings = []
        self.bullet_masses = {}     # link -> the mass pybullet is given (urdf_masses)

    @property
    def visuals(self):
        """Link name -> list of :class:`Visual` (every link present)."""
        return OrderedDict((name, link.visuals) for name, link in self.links.items())

    def parent_joint(self, link):
        """The joint whose child is ``link``, or None for the root."""
        return next((j for j in self.joints.values() if j.child == link), None)

    def link_frame(self, link):
        """4x4 frame of ``link`` in the root link's frame, every joint at zero."""
        frame = np.eye(4)
        joint = self.parent_joint(link)
        while joint is not None:
            frame = joint.origin.dot(frame)
            joint = self.parent_joint(joint.parent)
        return frame

    def joint_axis_in_root(self, name):
        """A joint's (position, unit axis) in the root link's frame."""
        joint = self.joints[name]
        frame = self.link_frame(joint.parent).dot(joint.origin)
        return frame[:3, 3], frame[:3, :3].dot(joint.axis)

    def bullet_text(self):
        """The URDF text pybullet loads: meshes at absolute paths."""
        tree = ET.fromstring(ET.tostring(self._tree))
        for mesh in tree.iter('mesh'):
            if mesh.get('filename'):
                mesh.set('filename', resolve_mesh_path(mesh.get('filename'), self.base_dir))
        for link in tree.findall('link'):
            if link.get('name') in self.bullet_masses:
                _set_mass(link, self.bullet_masses[link.get('name')])
        return ET.tostring(tree, encoding='unicode')


def _set_mass(link, mass):
    inertial = link.find('inertial')
    if inertial is None:
        inertial = ET.SubElement(link, 'inertial')
        ET.SubElement(inertial, 'inertia', ixx='0', ixy='0', ixz='0', iyy='0', iyz='0', izz='0')
    if inertial.find('mass') is None:
        ET.SubElement(inertial, 'mass')
    inertial.find('mass').set('value', '%.9g' % mass)


def _geometry(elem, where, base_dir):
    geom = elem.find('geometry')
    shape = geom[0] if geom is not None and len(geom) else None
    if shape is None:
        raise UrdfError('%s: no geometry' % where)
    kind, a = shape.tag, shape.attrib
    try:
        if kind == 'box':
            size = floats(a.get('size'), 3, (1, 1, 1), where + ' box size')
            return kind, {'size': _extents(size, where, kind, 'size')}
        if kind in ('cylinder', 'capsule'):
            return kind, {'radius': _extents([float(a['radius'])], where, kind, 'radius')[0],
                          'length': _extents([float(a['length'])], where, kind, 'length')[0]}
        if kind == 'sphere':
            return kind, {'radius': _extents([float(a['radius'])], where, kind, 'radius')[0]}
        if kind == 'mesh':
            scale = floats(a.get('scale'), 3, (1, 1, 1), where + ' scale')
            _extents([abs(s) for s in scale], where, kind, 'scale')
            return kind, {'filename': resolve_mesh_path(a['filename'], base_dir),
                          'scale': scale}
    except UrdfError:
        raise           # already says where
    except (KeyError, ValueError) as exc:
        raise UrdfError('%s: <%s> %s' % (where, kind, exc))
    return kind, {}    # an unknown shape: kept, not drawn (the renderer says so)


def _extents(values, where, kind, name):
    """``values`` if each is a size pybullet can hold: finite, in [0, MAX_EXTENT]."""
    if not all(math.isfinite(v) and 0.0 <= v <= MAX_EXTENT for v in values):
        raise UrdfError('%s: <%s> %s %s: each must be in [0, %g]'
                        % (where, kind, name, ' '.join('%.10g' % v for v in values),
                           MAX_EXTENT))
    return tuple(values)


def _materials(root, where):
    """Named materials: top level first, then any named inline one."""
    materials = {}
    for level in (root.findall('material'), root.iter('material')):
        for m in level:
            c = m.find('color')
            if c is not None and m.get('name') and m.get('name') not in materials:
                materials[m.get('name')] = floats(c.get('rgba'), 4, DEFAULT_RGBA,
                                                  '%s material %s' % (where, m.get('name')))
    return materials


def _link(elem, materials, gazebo_colour, base_dir):
    name = elem.get('name')
    visuals, collisions = [], []
    for kind, out in (('visual', visuals), ('collision', collisions)):
        for v in elem.findall(kind):
            where = 'link %s %s' % (name, kind)
            shape, params = _geometry(v, where, base_dir)
            rgba = DEFAULT_RGBA
            mat = v.find('material')
            if mat is not None:
                c = mat.find('color')
                rgba = (floats(c.get('rgba'), 4, DEFAULT_RGBA, where + ' color')
                        if c is not None else materials.get(mat.get('name'), DEFAULT_RGBA))
            if gazebo_colour is not None:
                rgba = gazebo_colour
            out.append(Visual(origin_matrix(v, where), shape, params, tuple(rgba)))
    return Link(name, visuals, collisions, _mass(elem.find('inertial'), name))


def _mass(inertial, name):
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


def _joint(elem):
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


def parse(text, base_dir='.'):
    """Read URDF ``text`` (meshes relative to ``base_dir``); UrdfError says why not."""
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise UrdfError('not a valid URDF: %s' % exc)
    if root.tag != 'robot':
        raise UrdfError('not a URDF: the root element is <%s>, not <robot>' % root.tag)
    name = root.get('name') or 'robot'
    tags = gazebo_tags.read(root)
    materials = _materials(root, 'robot %s' % name)
    links = OrderedDict()
    for elem in root.findall('link'):
        if not elem.get('name'):
            raise UrdfError('robot %s: a link has no name' % name)
        links[elem.get('name')] = _link(elem, materials, tags.colours.get(elem.get('name')),
                                        base_dir)
    if not links:
        raise UrdfError('robot %s has no link' % name)
    joints = OrderedDict((j.name, j) for j in (_joint(e) for e in root.findall('joint')))
    for j in joints.values():
        for end in (j.parent, j.child):
            if end not in links:
                raise UrdfError('joint %s: no link %r' % (j.name, end))
    roots = [n for n in links if n not in {j.child for j in joints.values()}]
    if len(roots) != 1:
        raise UrdfError('robot %s: %d root links (%s); a URDF is one tree'
                        % (name, len(roots), ', '.join(roots)))
    # Gazebo ignores a tag for a link it does not have; so do we, but say so
    unknown = ['<gazebo reference="%s">: no link or joint of that name; ignored' % ref
               for ref in tags.references() if ref not in links and ref not in joints]
    dropped, lines = set(), []
    if not tags.static and roots[0] not in tags.gravity_off:
        try:
            dropped, lines = urdf_masses.left_out(
                roots[0], {n: link.mass for n, link in links.items()}, joints.values())
        except urdf_masses.MasslessRoot as exc:
            raise UrdfError(str(exc))
    if dropped:
        tags = _leave_out(root, dropped, joints)
        links = OrderedDict((n, link) for n, link in links.items() if n not in dropped)
        joints = OrderedDict((n, j) for n, j in joints.items() if j.child not in dropped)
    model = UrdfModel(name, roots[0], links, joints, tags, root, base_dir)
    model.warnings = unknown + lines
    if not tags.static and roots[0] not in tags.gravity_off:
        model.bullet_masses = urdf_masses.bullet_masses(
            roots[0], {n: link.mass for n, link in links.items()}, joints.values())
    return model


def _leave_out(root, dropped, joints):
    """Remove the links Gazebo does not model from the tree, with their joints
    and their ``<gazebo reference>`` tags; the tags read again."""
    names = set(dropped) | {j.name for j in joints.values() if j.child in dropped}
    for elem in list(root):
        if (elem.tag == 'link' and elem.get('name') in dropped) or \
                (elem.tag == 'joint' and elem.get('name') in names) or \
                (elem.tag == 'gazebo' and elem.get('reference') in names):
            root.remove(elem)
    return gazebo_tags.read(root)

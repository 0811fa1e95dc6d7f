"""A URDF read once, for physics and drawing alike (no ROS, no pybullet, no GL).

:func:`parse` turns URDF text into a :class:`UrdfModel` as urdfdom and Gazebo
read it (each element read by :mod:`.urdf_elements`, each link by
:mod:`.urdf_links`: what urdfdom cannot read of a link is left out with its
error line, not refused): links with their visuals, collisions and inertials,
joints with origins, axes and limits, materials resolved to RGBA, mesh paths
resolved (``package://``, relative to the file), and the ``<gazebo>``
extension tags read by :mod:`exp_assignment2.sim.gazebo_tags` (plugins,
sensors, Gazebo colours, static models). A link coloured by ``<gazebo
reference><material>`` is drawn in that colour, as Gazebo draws it. Links
without mass are modeled as Gazebo 11 models them (:mod:`.urdf_masses`): what
Gazebo leaves out is left out, with one warning line each. A fixed or
floating joint's axis is not read (urdfdom does not); a moving joint's zero
axis is the world's x as the model was spawned (Gazebo's ODE normalises a zero
axis to x, in world coordinates).
:meth:`UrdfModel.bullet_text` is the text pybullet loads: mesh paths made
absolute, what Gazebo does not build left out.
"""
import xml.etree.ElementTree as ET
from collections import OrderedDict

import numpy as np

from exp_assignment2.sim import gazebo_tags, urdf_links, urdf_masses
from exp_assignment2.sim.rotations import rpy_matrix
from exp_assignment2.sim.urdf_elements import (AXISLESS_JOINTS, UrdfError, joint,
                                               materials as read_materials, resolve_mesh_path)

class UrdfModel(object):
    """A parsed URDF. ``links`` and ``joints`` are ordered dicts by name;
    ``root`` is the root link's name; ``gazebo`` the :class:`~.gazebo_tags.GazeboTags`."""

    def __init__(self, name, root, links, joints, gazebo, tree, base_dir):
        self.name, self.root, self.links, self.joints = name, root, links, joints
        self.gazebo, self._tree, self.base_dir = gazebo, tree, base_dir
        self.warnings = []          # lines for the log, as Gazebo's warnings
        self.errors = []            # lines for the log, as urdfdom's and Gazebo's errors
        self.bullet_masses = {}     # link -> the mass pybullet is given (urdf_masses)

    @property
    def visuals(self):
        """Link name -> list of :class:`~.urdf_elements.Visual` (every link present)."""
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


def parse(text, base_dir='.', spawn_rpy=(0.0, 0.0, 0.0)):
    """Read URDF ``text`` (meshes relative to ``base_dir``; ``spawn_rpy``: the
    orientation it is spawned at, for a zero joint axis); UrdfError says why not."""
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise UrdfError('not a valid URDF: %s' % exc)
    if root.tag != 'robot':
        raise UrdfError('not a URDF: the root element is <%s>, not <robot>' % root.tag)
    name = root.get('name') or 'robot'
    tags = gazebo_tags.read(root)
    materials, errors = read_materials(root, 'robot %s' % name)
    links = OrderedDict()
    for elem in root.findall('link'):
        if not elem.get('name'):
            raise UrdfError('robot %s: a link has no name' % name)
        links[elem.get('name')], lines = urdf_links.read(
            elem, materials, tags.colours.get(elem.get('name')), base_dir)
        errors += lines
    if not links:
        raise UrdfError('robot %s has no link' % name)
    joints = OrderedDict((j.name, j) for j in (joint(e) for e in root.findall('joint')))
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
    model.warnings = unknown + lines + _axes_as_gazebo(model, root, spawn_rpy)
    model.errors = errors
    if not tags.static and roots[0] not in tags.gravity_off:
        model.bullet_masses = urdf_masses.bullet_masses(
            roots[0], {n: link.mass for n, link in links.items()}, joints.values())
    return model


def _axes_as_gazebo(model, root, spawn_rpy):
    """A fixed or floating joint's ``<axis>`` is not read, so not given to
    pybullet; a moving joint's zero axis becomes the world's x at the spawn,
    in the joint's frame, as ODE's dJointSetHingeAxis makes it. One warning
    line per zero axis (Gazebo says nothing: ODE's message is commented out)."""
    lines, spawn = [], rpy_matrix(*spawn_rpy)
    for elem in root.findall('joint'):
        j = model.joints.get(elem.get('name'))
        if j is None:
            continue
        if j.type in AXISLESS_JOINTS:
            for axis in elem.findall('axis'):
                elem.remove(axis)
        elif not j.axis.any():
            world = spawn.dot(model.link_frame(j.parent)[:3, :3]).dot(j.origin[:3, :3])
            axis = world.T.dot(np.array((1.0, 0.0, 0.0)))
            model.joints[j.name] = j._replace(axis=axis)
            for element in elem.findall('axis'):
                element.set('xyz', ' '.join('%.12g' % v for v in axis))
            lines.append('joint %s: the axis is 0 0 0: urdfdom reads it and Gazebo\'s ODE turns '
                         'the %s joint about the world\'s x axis as the model was spawned '
                         '(axis %s in the joint\'s frame); so does the simulator'
                         % (j.name, j.type, ' '.join('%.3g' % v for v in axis)))
    return lines


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

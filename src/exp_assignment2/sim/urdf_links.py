"""A URDF link read as urdfdom reads it, and as Gazebo then builds it (no ROS,
no pybullet, no GL).

urdfdom's parseLink reads a link's ``<inertial>``, then its ``<visual>``
elements, then its ``<collision>`` elements, and stops at the first one it
cannot read: it logs why, and ``Could not parse visual element for Link
[X]``; and parseURDF ignores what parseLink returns, so the robot loads with
the link as far as it was read (model.cpp, in every release: urdfdom 0.4 of
Kinetic, 1.0 of Melodic and Noetic). So:

* an unreadable ``<inertial>`` (no ``<mass>``, no ``<inertia>``, a number
  that is not one) leaves the link the mass read before it (0 when the mass
  itself was not read) and none of its visuals and collisions;
* an unreadable visual (no geometry, an unknown shape, a visual
  ``<material>`` without a name...) is dropped with the visuals after it and
  every collision; an unreadable collision with the collisions after it;
* a bad inline colour is logged and the visual is drawn without it.

And Gazebo (common::MeshManager) logs ``Unable to find file[F]`` for a mesh
whose file does not exist, and draws or collides nothing for it: such a
visual or collision is left out here too, as is a mesh in a format pybullet
does not read (it would refuse the robot for it).

:func:`read` returns the :class:`~.urdf_elements.Link` and the error lines,
and removes from the element what is left out, so the text pybullet loads
holds what Gazebo holds. What would break the world
(:class:`~.urdf_elements.BreaksTheWorld`) is raised, not dropped.
"""
import os
import xml.etree.ElementTree as ET

from exp_assignment2.sim.urdf_elements import (DEFAULT_RGBA, BreaksTheWorld, Link, UrdfError,
                                               Visual, geometry, mass as read_mass,
                                               material_colour, origin_matrix)

INERTIA = ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz')
MESH_EXTENSIONS = ('.stl', '.obj', '.dae')     # what pybullet's URDF importer reads


def read(elem, materials, gazebo_colour, base_dir):
    """(Link, [error lines]) of a ``<link>`` element (see the module docstring)."""
    name = elem.get('name')
    lines = []
    inertial = elem.find('inertial')
    mass, readable = 0.0, True
    if inertial is not None:
        try:
            mass = read_mass(inertial, name)
        except BreaksTheWorld:
            raise
        except UrdfError as exc:
            mass, readable = exc.mass, False
            _keep_mass(elem, inertial, mass)
            lines.append(_stopped(elem, name, 'inertial', str(exc), elem.findall('visual') +
                                  elem.findall('collision')))
    shapes = {'visual': [], 'collision': []}
    for kind in ('visual', 'collision'):
        if not readable:
            break
        elements = elem.findall(kind)
        for i, child in enumerate(elements):
            where = 'link %s %s' % (name, kind)
            try:
                shape, params = geometry(child, where, base_dir)
                rgba, error = _colour(child, materials, where) if kind == 'visual' \
                    else (None, None)
                origin = origin_matrix(child, where)
            except BreaksTheWorld:
                raise
            except UrdfError as exc:
                rest = elements[i:] + (elem.findall('collision') if kind == 'visual' else [])
                lines.append(_stopped(elem, name, kind, str(exc), rest))
                readable = False
                break
            if error:
                lines.append(error)
            unread = shape == 'mesh' and _unread(params['filename'], kind, where)
            if unread:
                elem.remove(child)
                lines.append(unread)
                continue
            colour = gazebo_colour if gazebo_colour is not None else rgba or DEFAULT_RGBA
            shapes[kind].append(Visual(origin, shape, params, tuple(colour)))
    return Link(name, shapes['visual'], shapes['collision'], mass), lines


def _unread(path, kind, where):
    """The line for a mesh that is not built (a missing file: Gazebo's
    MeshManager says so and builds nothing; a format pybullet refuses the
    whole robot for), else None."""
    what = 'draws' if kind == 'visual' else 'collides with'
    if not os.path.exists(path):
        return ('%s: Unable to find file[%s]: Gazebo %s nothing for it; left out here too'
                % (where, path, what))
    extension = os.path.splitext(path)[1].lower()
    if extension not in MESH_EXTENSIONS:
        return ('%s: a %s mesh (%s) is not read here (STL, OBJ and COLLADA are): left out; '
                'Gazebo %s it if it reads the format, else logs "Invalid mesh filename '
                'extension"' % (where, extension or 'nameless', path, what))
    return None


def _colour(visual, materials, where):
    mat = visual.find('material')
    if mat is None:
        return None, None
    if not mat.get('name'):
        raise UrdfError('%s: Visual material must contain a name attribute' % where)
    return material_colour(mat, materials, where)


def _stopped(elem, name, kind, reason, dropped):
    """urdfdom's two lines as one; the elements it did not read removed."""
    for child in dropped:
        elem.remove(child)
    counts = [(k, sum(1 for c in dropped if c.tag == k)) for k in ('visual', 'collision')]
    lost = ', '.join('%d %s%s' % (n, k, 's' if n > 1 else '') for k, n in counts if n)
    return ('%s; Could not parse %s element for Link [%s] (urdfdom stops reading the link '
            'there, and Gazebo builds it as read): %s left out here too'
            % (reason, kind, name, lost or 'nothing'))


def _keep_mass(elem, inertial, mass):
    """The inertial as urdfdom kept it: the mass read, no inertia."""
    elem.remove(inertial)
    if mass > 0:
        kept = ET.SubElement(elem, 'inertial')
        ET.SubElement(kept, 'mass', value='%.10g' % mass)
        ET.SubElement(kept, 'inertia', {key: '0' for key in INERTIA})

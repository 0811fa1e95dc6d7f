"""SDF worlds and models as URDF models (plain Python: no rospy, no pybullet).

A Gazebo user's ``worlds/*.world`` (SDF: a ground plane, a sun, boxes,
``model://`` meshes from Gazebo's model database) and the models they spawn
with ``spawn_model -sdf`` are read here into what the simulator spawns: one
URDF robot per model (:mod:`.sdf_model`).

* :func:`read_world` -> :class:`SdfWorld`: ``models`` [(name, urdf, pose,
  static)] in the file's order, each at its pose, or at the pose the world's
  saved ``<state>`` gives it (as Gazebo applies the first state on load);
  ``gravity``; ``physics`` (the numbers of ``<physics>``); ``notes`` (one line
  per stand-in used, one per element skipped).
* :func:`model_to_urdf`: one SDF model (or a world holding one model or
  include, as ``spawn_model -database`` sends) as URDF text.

Shapes: box, cylinder, sphere, plane (a thin box whose top face is the plane),
STL/OBJ meshes that are installed. Any other mesh becomes a box of the model's
known size from ``config/gazebo_model_sizes.yaml``; a visual's mesh of a model
the table does not know, a box of the size its link declares (the box bounding
the link's box, cylinder and sphere collisions, as Gazebo models give them
beside a mesh), else a 1 m box scaled by the mesh's ``<scale>``, seen and not
collided with (:data:`.sdf_sources.DEFAULT_MESH_BOX`). ``<include>`` of
``model://NAME``: the installed model (``GAZEBO_MODEL_PATH``,
``~/.gazebo/models``), else Gazebo's ``ground_plane`` and ``sun``, else a box
of the known size. Lights are not simulated and are skipped; actors,
populations, roads and world plugins are skipped with a note. What cannot be
read raises :class:`SdfError` naming the element, e.g.
``world/model[wall]/link[link]/visual[v]/geometry: unknown shape <heightmap>``.
"""
import os
from collections import namedtuple

from exp_assignment2.sim.sdf_geometry import SdfError, floats, pose_of, pose_tuple
from exp_assignment2.sim.sdf_model import read_model
from exp_assignment2.sim.sdf_to_urdf import model_urdf
from exp_assignment2.sim.sdf_sources import SIZES_FILE, Sources, load_model_sizes, parse_xml

__all__ = ['SdfError', 'SdfWorld', 'WorldModel', 'read_world', 'model_to_urdf', 'model_pose',
           'load_model_sizes', 'SIZES_FILE']

# world elements that make something in Gazebo but not here: one note each
NOT_SIMULATED = {'actor': 'animated actors', 'population': 'populations of models',
                 'road': 'roads', 'plugin': 'world plugins'}

WorldModel = namedtuple('WorldModel', 'name urdf pose static')
WorldModel.__doc__ = """A model of a world: URDF text, pose (x, y, z, roll,
pitch, yaw) in the world and whether it is static."""


class SdfWorld(object):
    """A world read from SDF: ``name``, ``models`` (:class:`WorldModel`),
    ``gravity`` (x, y, z), ``physics`` (dict of ``<physics>`` numbers such as
    max_step_size, real_time_factor) and ``notes`` (the stand-ins used)."""

    def __init__(self, name, models, gravity, physics, notes, warnings=()):
        self.name, self.models, self.gravity = name, models, gravity
        self.physics, self.notes, self.warnings = physics, notes, list(warnings)


def read_world(path_or_text, sizes=None, model_path=None):
    """Read an SDF world (a file path or its text) into an :class:`SdfWorld`."""
    is_text = path_or_text.lstrip().startswith('<')
    label = 'world' if is_text else path_or_text
    root = parse_xml(path_or_text, label)
    if root.tag != 'sdf':
        raise SdfError('%s: the root element is <%s>, not <sdf>%s' % (
            label, root.tag, ': this is a URDF' if root.tag == 'robot' else ''))
    world = root.find('world')
    if world is None:
        raise SdfError('%s: no <world> in <sdf>' % label)
    context = Sources(sizes, model_path,
                       os.getcwd() if is_text else os.path.dirname(os.path.abspath(path_or_text)))
    gravity = world.find('gravity')
    if gravity is None:
        gravity = world.find('physics/gravity')
    gravity = (0.0, 0.0, -9.8) if gravity is None else tuple(
        _floats_or_error(gravity.text, 'world/gravity'))
    physics = {}
    for tag in ('max_step_size', 'real_time_factor', 'real_time_update_rate'):
        text = world.findtext('physics/' + tag)
        if text is not None:
            physics[tag] = _floats_or_error(text, 'world/physics/' + tag, 1)[0]
    state = world.find('state')
    saved = {} if state is None else {
        m.get('name'): pose_of(m, 'world/state/model[%s]' % m.get('name'))
        for m in state.findall('model') if m.find('pose') is not None}
    models, names, skipped, warnings = [], set(), [], []
    for child in world:
        context.model = child.get('name') or child.findtext('name', '') or \
            child.findtext('uri', '')
        if child.tag == 'model':
            model = read_model(child, 'world/model[%s]' % child.get('name', ''), context)
        elif child.tag == 'include':
            model = context.include(child, 'world')
            if model is None:
                continue
        else:
            if child.tag in NOT_SIMULATED:
                skipped.append('world/%s[%s]: %s are not simulated here: skipped' % (
                    child.tag, child.get('name', ''), NOT_SIMULATED[child.tag]))
            continue
        if not model.links:     # Gazebo holds an empty model; nothing of it to simulate
            skipped.append('world/model[%s]: no <link>: an empty model, skipped' % model.name)
            continue
        if model.name in names:
            raise SdfError('world/model[%s]: two models are called %r' % (model.name,
                                                                          model.name))
        names.add(model.name)
        urdf = model_urdf(model)
        warnings.extend(model.warnings)
        pose = saved.get(model.name, model.pose)
        models.append(WorldModel(model.name, urdf, pose_tuple(pose),
                                 model.static or model.fixed_to_world))
    return SdfWorld(world.get('name', 'default'), models, gravity, physics,
                    context.notes() + skipped, warnings)


def _floats_or_error(text, where, count=3):
    return floats(text, count, where, 'the value')


def _one_model(sdf_text):
    """The ``<model>`` or ``<include>`` element a spawn request carries."""
    root = parse_xml(sdf_text, 'sdf')
    if root.tag == 'model':
        return root
    holder = root.find('world') if root.tag == 'sdf' and root.find('model') is None else root
    if root.tag != 'sdf' or holder is None:
        raise SdfError('sdf: expected <sdf> holding one <model>, not <%s>' % root.tag)
    found = [e for e in holder if e.tag in ('model', 'include')]
    if len(found) != 1:
        raise SdfError('sdf: expected one <model> (or one <include> in a <world>), found %d'
                       % len(found))
    return found[0]


def model_to_urdf(sdf_text, name=None, sizes=None, model_path=None, notes=None):
    """URDF text of the one model in ``sdf_text``, named ``name`` (default: the
    model's). The model's own ``<pose>`` is not part of it (:func:`model_pose`);
    stand-in lines and warnings are appended to ``notes`` when it is a list."""
    elem = _one_model(sdf_text)
    context = Sources(sizes, model_path, os.getcwd())
    context.model = name or elem.get('name', '')
    if elem.tag == 'model':
        model = read_model(elem, 'model[%s]' % elem.get('name', ''), context)
    else:
        model = context.include(elem, 'world')
        if model is None:
            raise SdfError('; '.join(context.skipped) or 'sdf: the include is a light, not a '
                           'model')
    if name:
        model.name = name
    if not model.links:
        raise SdfError('model[%s]: the model has no <link> (Gazebo would spawn it empty)'
                       % model.name)
    urdf = model_urdf(model)
    if notes is not None:
        notes.extend(context.notes() + model.warnings)
    return urdf


def model_pose(sdf_text):
    """(x, y, z, roll, pitch, yaw) of the model's own ``<pose>`` in ``sdf_text``."""
    elem = _one_model(sdf_text)
    return pose_tuple(pose_of(elem, '%s[%s]' % (elem.tag, elem.get('name', ''))))

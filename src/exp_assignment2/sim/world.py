"""A world YAML: which models to spawn at start, where (no ROS, no pybullet).

A world is a dict (the ``~`` parameters of the simulator node, loaded from
``config/world_*.yaml``)::

    bounds: [x_min, x_max, y_min, y_max]   # no driven body leaves this square; Gazebo's
                                           # services place bodies within it and 1 m,
                                           # and the world has a floor: a body 10 m
                                           # beyond it, or under the floor, is put back
    models:
      - name: robot
        description: robot_description   # URDF text on the parameter server,
                                         # relative to the namespace
        # or urdf: robot.urdf            # a file (relative: the urdf/ folder)
        pose: [x, y, z, yaw]             # or [x, y, z, roll, pitch, yaw]
        namespace: robot                 # the robot namespace of its plugins
        grid: false                      # draw a 1 m grid on its base link

A model's plugins come from its URDF's ``<gazebo>`` tags, as in Gazebo.
:func:`parse_world` checks everything and raises ``ValueError`` naming the
offending model and key, so a typo in a YAML file is an error, not a silent
default.
"""
import math
from dataclasses import dataclass

MODEL_KEYS = ('name', 'urdf', 'description', 'pose', 'namespace', 'grid')
WORLD_KEYS = ('models', 'bounds')


@dataclass
class ModelSpec:
    """One model of the world, checked."""
    name: str
    urdf: str = ''                 # file, or '' when ``description`` is used
    description: str = ''          # parameter holding the URDF text
    pose: tuple = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    namespace: str = ''
    grid: bool = False

    def description_param(self):
        """The parameter holding the URDF: relative names are in the namespace."""
        if self.description.startswith('/'):
            return self.description
        ns = self.namespace.strip('/')
        return '/%s/%s' % (ns, self.description) if ns else '/' + self.description


@dataclass
class WorldSpec:
    models: list
    bounds: tuple = (-math.inf, math.inf, -math.inf, math.inf)


def number(value, what, positive=False):
    """``value`` as a finite float, or ValueError naming ``what``."""
    if isinstance(value, bool):
        raise ValueError('%s must be a number, got %r' % (what, value))
    try:
        result = float(value)
    except (TypeError, ValueError):
        raise ValueError('%s must be a number, got %r' % (what, value))
    if not math.isfinite(result) or (positive and result <= 0):
        raise ValueError('%s must be %s, got %r' % (what, 'positive' if positive else 'finite',
                                                    value))
    return result


def _check_keys(given, known, where):
    unknown = sorted(set(given) - set(known))
    if unknown:
        hint = (' (plugins now come from the URDF\'s <gazebo> tags)'
                if 'plugins' in unknown else '')
        raise ValueError('%s: unknown key %s (known: %s)%s'
                         % (where, ', '.join(repr(k) for k in unknown), ', '.join(known), hint))


def parse_model(desc):
    """Check one model description (a dict) and return a :class:`ModelSpec`."""
    if not isinstance(desc, dict):
        raise ValueError('a model must be a mapping, got %r' % (desc,))
    where = 'model %s' % desc.get('name', '?')
    _check_keys(desc, MODEL_KEYS, where)
    if not desc.get('name'):
        raise ValueError('%s has no name' % where)
    if bool(desc.get('urdf')) == bool(desc.get('description')):
        raise ValueError('%s: give exactly one of urdf (a file) or description (a parameter)'
                         % where)
    pose = desc.get('pose', [0, 0, 0, 0])
    if not isinstance(pose, (list, tuple)) or len(pose) not in (4, 6):
        raise ValueError('%s: pose must be [x, y, z, yaw] or [x, y, z, roll, pitch, yaw], '
                         'got %r' % (where, pose))
    pose = tuple(number(v, '%s: pose' % where) for v in pose)
    if len(pose) == 4:
        pose = pose[:3] + (0.0, 0.0, pose[3])
    return ModelSpec(name=str(desc['name']), urdf=str(desc.get('urdf') or ''),
                     description=str(desc.get('description') or ''), pose=pose,
                     namespace=str(desc.get('namespace', '')).strip('/'),
                     grid=bool(desc.get('grid', False)))


def parse_world(params):
    """Check a world (dict with ``models`` and optional ``bounds``)."""
    if not isinstance(params, dict):
        raise ValueError('a world must be a mapping with a models list')
    _check_keys(params, WORLD_KEYS, 'world')
    descs = params.get('models', [])
    if not isinstance(descs, (list, tuple)):
        raise ValueError('world: models must be a list')
    models = [parse_model(d) for d in descs]
    names = [m.name for m in models]
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise ValueError('world: model names must be unique, repeated: %s' % repeated)
    bounds = params.get('bounds', WorldSpec.__dataclass_fields__['bounds'].default)
    if not isinstance(bounds, (list, tuple)) or len(bounds) != 4:
        raise ValueError('world: bounds must be [x_min, x_max, y_min, y_max]')
    bounds = tuple(float(b) for b in bounds)
    if not (bounds[0] < bounds[1] and bounds[2] < bounds[3]):
        raise ValueError('world: bounds %s are empty' % (bounds,))
    return WorldSpec(models=models, bounds=bounds)

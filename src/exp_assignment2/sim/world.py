"""The simulator's world description: which models, where, with which plugins.

A world is a dict (the ``~`` parameters of the simulator node, loaded from
``config/world_*.yaml``)::

    bounds: [x_min, x_max, y_min, y_max]   # no driven body leaves this square
    models:
      - name: robot
        description: /robot/robot_description   # URDF text on the parameter server
        # or urdf: robot.urdf                    # a file (relative: the urdf/ folder)
        pose: [x, y, z, yaw]
        namespace: robot                         # prefixes the model's topics
        base_frame: link_chassis
        grid: false                              # draw a 1 m grid on its upward faces
        plugins:                                 # one feature each, see PLUGIN_OPTIONS
          diff_drive: {max_linear: 2.0}
          odometry: {rate: 50}

:func:`parse_world` checks everything and raises ``ValueError`` naming the
offending model and key, so a typo in a YAML file is an error, not a silent
default. Plain Python: no ROS, no pybullet.
"""
import math
from dataclasses import dataclass, field

# Every plugin and its options with their defaults; None = required (or, for
# diff_drive's wheels, read from the URDF's Gazebo diff-drive plugin).
PLUGIN_OPTIONS = {
    'diff_drive': dict(left_joint=None, right_joint=None, wheel_radius=None,
                       wheel_separation=None, wheel_torque=20.0, max_linear=2.0,
                       max_angular=3.0, cmd_timeout=0.5, topic='cmd_vel'),
    'planar_move': dict(kinematic=False, max_linear=2.0, max_angular=3.0, cmd_timeout=0.5,
                        topic='cmd_vel'),
    'joint_position': dict(joint=None, topic='joint_position_controller/command',
                           max_velocity=2.0, effort=5.0),
    'height': dict(topic='height_controller/command', max_z=50.0),
    'odometry': dict(rate=50.0, topic='odom', frame='odom', tf=True),
    'joint_states': dict(rate=50.0, topic='joint_states'),
    'camera': dict(link=None, name='camera1', width=800, height=800, rate=30.0, hfov=80.0,
                   near=0.05, far=40.0, jpeg_quality=80),
}
DRIVES = ('diff_drive', 'planar_move')
MODEL_KEYS = ('name', 'urdf', 'description', 'pose', 'namespace', 'base_frame', 'grid',
              'plugins')
WORLD_KEYS = ('models', 'bounds')


@dataclass
class ModelSpec:
    """One model of the world, checked."""
    name: str
    urdf: str = ''                 # file, or '' when ``description`` is used
    description: str = ''          # parameter holding the URDF text
    pose: tuple = (0.0, 0.0, 0.0, 0.0)
    namespace: str = ''
    base_frame: str = 'base_link'
    grid: bool = False
    plugins: dict = field(default_factory=dict)   # name -> options (defaults filled)

    def topic(self, name):
        """The model's topic ``name`` under its namespace."""
        ns = self.namespace.strip('/')
        return '/%s/%s' % (ns, name) if ns else '/' + name

    @property
    def drive(self):
        """The name of the model's drive plugin, or None for scenery."""
        return next((d for d in DRIVES if d in self.plugins), None)


@dataclass
class WorldSpec:
    models: list
    bounds: tuple = (-math.inf, math.inf, -math.inf, math.inf)

    def model(self, name):
        return next(m for m in self.models if m.name == name)


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
        raise ValueError('%s: unknown key %s (known: %s)'
                         % (where, ', '.join(repr(k) for k in unknown), ', '.join(known)))


NUMERIC_REQUIRED = ('wheel_radius', 'wheel_separation')


def _option(value, default, key, what):
    if isinstance(default, bool):
        if not isinstance(value, bool):
            raise ValueError('%s must be true or false, got %r' % (what, value))
        return value
    if isinstance(default, (int, float)) or key in NUMERIC_REQUIRED:
        if key == 'cmd_timeout':
            value = number(value, what)
            if value < 0:
                raise ValueError('%s must be >= 0 (0: keep the last command), got %r'
                                 % (what, value))
            return value
        value = number(value, what, positive=True)
        return int(value) if isinstance(default, int) else value
    if not isinstance(value, str) or not value:
        raise ValueError('%s must be a non-empty string, got %r' % (what, value))
    return value


def plugin_options(name, given, where):
    """The options of plugin ``name``: ``given`` checked against the defaults."""
    if name not in PLUGIN_OPTIONS:
        raise ValueError('%s: unknown plugin %r (known: %s)'
                         % (where, name, ', '.join(sorted(PLUGIN_OPTIONS))))
    given = given or {}
    if not isinstance(given, dict):
        raise ValueError('%s: options of plugin %s must be a mapping, got %r'
                         % (where, name, given))
    defaults = PLUGIN_OPTIONS[name]
    _check_keys(given, defaults, '%s: plugin %s' % (where, name))
    options = dict(defaults)
    for key, value in given.items():
        options[key] = _option(value, defaults[key], key,
                               '%s: plugin %s: %s' % (where, name, key))
    return options


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
    if not isinstance(pose, (list, tuple)) or len(pose) != 4:
        raise ValueError('%s: pose must be [x, y, z, yaw], got %r' % (where, pose))
    plugins = desc.get('plugins') or {}
    if not isinstance(plugins, dict):
        raise ValueError('%s: plugins must be a mapping of plugin: options' % where)
    spec = ModelSpec(
        name=str(desc['name']), urdf=str(desc.get('urdf') or ''),
        description=str(desc.get('description') or ''),
        pose=tuple(number(v, '%s: pose' % where) for v in pose),
        namespace=str(desc.get('namespace', '')),
        base_frame=str(desc.get('base_frame', 'base_link')), grid=bool(desc.get('grid', False)),
        plugins={name: plugin_options(name, opts, where) for name, opts in plugins.items()})
    if sum(d in spec.plugins for d in DRIVES) > 1:
        raise ValueError('%s: at most one drive (%s)' % (where, ', '.join(DRIVES)))
    return spec


def parse_world(params):
    """Check a world (dict with ``models`` and optional ``bounds``)."""
    if not isinstance(params, dict):
        raise ValueError('a world must be a mapping with a models list')
    _check_keys(params, WORLD_KEYS, 'world')
    descs = params.get('models')
    if not isinstance(descs, (list, tuple)) or not descs:
        raise ValueError('world: models must be a non-empty list')
    models = [parse_model(d) for d in descs]
    names = [m.name for m in models]
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise ValueError('world: model names must be unique, repeated: %s' % repeated)
    bounds = params.get('bounds', WorldSpec.__dataclass_fields__['bounds'].default)
    if len(bounds) != 4:
        raise ValueError('world: bounds must be [x_min, x_max, y_min, y_max]')
    bounds = tuple(float(b) for b in bounds)
    if not (bounds[0] < bounds[1] and bounds[2] < bounds[3]):
        raise ValueError('world: bounds %s are empty' % (bounds,))
    return WorldSpec(models=models, bounds=bounds)


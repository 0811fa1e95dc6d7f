"""The worlds of both scenarios, as plain data.

The simulator reads a list of model descriptions (from the ``~models``
parameter, see ``config/world_*.yaml``); :func:`parse_models` checks them and
turns them into :class:`ModelSpec` objects. The constants describe the
arenas the behaviours live in.
"""
import math
from dataclasses import dataclass, field

# Scenario A: dog and ball.
ARENA_GOAL_LIMIT = 8.0          # goals live in x, y in [-8, 8]
DOG_HOME = (7.0, 7.0)           # the kennel
# Scenario B: MiRo on a 10 x 10 m grid.
GRID_MIN, GRID_MAX = 0, 10
MIRO_HOME = (3, 3)

MODEL_KINDS = ('static', 'diff_drive', 'omni', 'kinematic')


@dataclass
class ModelSpec:
    """One model of the world and how the simulator drives it.

    ``kind``: ``static`` (scenery), ``diff_drive`` (wheels from cmd_vel),
    ``omni`` (planar velocity from cmd_vel, like Gazebo's planar_move),
    ``kinematic`` (moved by cmd_vel with no physics: the ball).
    ``namespace`` prefixes the model's topics ('' for none).
    """
    name: str
    urdf: str
    kind: str = 'static'
    pose: tuple = (0.0, 0.0, 0.0, 0.0)     # x, y, z, yaw
    namespace: str = ''
    base_frame: str = 'base_link'
    grid_texture: bool = False
    visible: bool = True               # kinematic bodies may start hidden
    wheel_radius: float = 0.1
    wheel_separation: float = 0.3
    max_wheel_torque: float = 20.0
    extra: dict = field(default_factory=dict)

    def topic(self, name):
        """The model's topic ``name`` under its namespace."""
        prefix = '/' + self.namespace.strip('/') if self.namespace.strip('/') else ''
        return '%s/%s' % (prefix, name)


def _number(value, what):
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError('%s must be a number, got %r' % (what, value))
    if not math.isfinite(number):
        raise ValueError('%s must be finite, got %r' % (what, value))
    return number


def parse_model(desc):
    """Check one model description (a dict) and return a :class:`ModelSpec`."""
    if not isinstance(desc, dict):
        raise ValueError('a model must be a dict, got %r' % (desc,))
    for key in ('name', 'urdf'):
        if not desc.get(key):
            raise ValueError('model %r has no %s' % (desc, key))
    name = str(desc['name'])
    kind = desc.get('kind', 'static')
    if kind not in MODEL_KINDS:
        raise ValueError('model %s: kind %r is not one of %s' % (name, kind, MODEL_KINDS))
    pose = list(desc.get('pose', [0, 0, 0, 0]))
    if len(pose) != 4:
        raise ValueError('model %s: pose must be [x, y, z, yaw], got %r' % (name, pose))
    pose = tuple(_number(v, 'model %s: pose' % name) for v in pose)
    known = set(ModelSpec.__dataclass_fields__) - {'extra'}
    kwargs = {k: v for k, v in desc.items() if k in known}
    kwargs.update(name=name, kind=kind, pose=pose, urdf=str(desc['urdf']))
    extra = {k: v for k, v in desc.items() if k not in known}
    for key in ('wheel_radius', 'wheel_separation', 'max_wheel_torque'):
        if key in kwargs:
            kwargs[key] = _number(kwargs[key], 'model %s: %s' % (name, key))
            if kwargs[key] <= 0:
                raise ValueError('model %s: %s must be positive' % (name, key))
    return ModelSpec(extra=extra, **kwargs)


def parse_models(descs):
    """Check a list of model descriptions; names must be unique."""
    if not isinstance(descs, (list, tuple)) or not descs:
        raise ValueError('~models must be a non-empty list of models')
    models = [parse_model(d) for d in descs]
    names = [m.name for m in models]
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise ValueError('model names must be unique, repeated: %s' % dupes)
    return models


def in_arena(x, y, limit=ARENA_GOAL_LIMIT):
    """True when (x, y) is a finite point inside the scenario-A goal square."""
    return (math.isfinite(x) and math.isfinite(y)
            and -limit <= x <= limit and -limit <= y <= limit)


def on_grid(x, y):
    """True when (x, y) is a point of scenario B's grid."""
    return (math.isfinite(x) and math.isfinite(y)
            and GRID_MIN <= x <= GRID_MAX and GRID_MIN <= y <= GRID_MAX)

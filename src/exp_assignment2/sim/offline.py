"""A world built without ROS, from the package's files: for the unit tests
and the benchmark, which run the simulator's own engine with no master.

The launch files put the robots' URDFs on the parameter server; here the
same files are read directly (:data:`DESCRIPTION_FILES`). ``registry``
chooses which plugins run (none by default: the tests drive the models
through the engine's own control laws).
"""
import os

import yaml

from exp_assignment2.layout import PACKAGE
from exp_assignment2.sim.engine import Engine
from exp_assignment2.sim.world import parse_world

URDF_DIR = os.path.join(PACKAGE, 'urdf')
ROBOT_MODELS = {'rep103': 'robot.urdf', 'original': 'robot_original.urdf'}
DESCRIPTION_FILES = {'/robot/robot_description': 'robot.urdf',
                     '/ball_description': 'ball.urdf', '/robot_description': 'miro.urdf'}


def load_world(name):
    """A world from ``config/`` (or a path)."""
    path = name if os.path.isabs(name) else os.path.join(PACKAGE, 'config', name)
    with open(path) as f:
        return parse_world(yaml.safe_load(f))


def urdf_text(spec, robot_model='rep103'):
    """A model's URDF text, as the launch files would provide it."""
    files = dict(DESCRIPTION_FILES, **{'/robot/robot_description': ROBOT_MODELS[robot_model]})
    name = spec.urdf or files[spec.description_param()]
    with open(os.path.join(URDF_DIR, name)) as f:
        return f.read()


def make_engine(world='world_dog.yaml', robot_model='rep103', registry=None, hidden=(),
                **kwargs):
    """An :class:`~exp_assignment2.sim.engine.Engine` with the world's models spawned."""
    spec = load_world(world) if isinstance(world, str) else world
    engine = Engine(registry=registry, bounds=spec.bounds, **kwargs)
    try:
        for model in spec.models:
            engine.spawn(model.name, urdf_text(model, robot_model), model.pose, model.namespace,
                         base_dir=URDF_DIR, grid=model.grid, hidden=model.name in hidden)
    except ValueError:
        engine.close()
        raise
    return engine

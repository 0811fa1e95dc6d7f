"""A world built without ROS, from the package's files: for the unit tests
and the benchmark, which run the simulator's own code with no master.

The launch files put the robots' URDFs on the parameter server; here the
same files are read directly (:data:`DESCRIPTION_FILES`).
"""
import os

import yaml

from exp_assignment2.sim.physics import Physics
from exp_assignment2.sim.world import parse_world

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
ROBOT_MODELS = {'rep103': 'robot.urdf', 'original': 'robot_original.urdf'}
DESCRIPTION_FILES = {'/robot/robot_description': 'robot.urdf',
                     '/ball_description': 'ball.urdf', '/robot_description': 'miro.urdf'}


def load_world(name):
    """A world from ``config/`` (or a path)."""
    path = name if os.path.isabs(name) else os.path.join(PACKAGE, 'config', name)
    with open(path) as f:
        return parse_world(yaml.safe_load(f))


def urdf_reader(robot_model='rep103'):
    """``read(spec)``: a model's URDF text, as the launch files would provide it."""
    files = dict(DESCRIPTION_FILES)
    files['/robot/robot_description'] = ROBOT_MODELS[robot_model]

    def read(spec):
        with open(os.path.join(PACKAGE, 'urdf', spec.urdf or files[spec.description])) as f:
            return f.read()
    return read


def make_physics(world='world_dog.yaml', robot_model='rep103', **kwargs):
    """The world's :class:`~exp_assignment2.sim.physics.Physics` (and its spec)."""
    spec = load_world(world) if isinstance(world, str) else world
    return Physics(spec, urdf_reader(robot_model), **kwargs)

"""The simulator's ROS features, one plugin each, chosen per model in the world.

Each plugin is built as ``Plugin(sim, model, options)`` (``sim`` is the
simulator node: physics, the command queue, the world's bounds) and may
define ``before_step()`` (apply commands), ``after_step(stamp)`` (publish),
``reset()`` and ``close()``. Subscriber callbacks never touch pybullet: they
queue work with ``sim.run_in_loop``.
"""
from exp_assignment2.sim.plugins.camera import CameraPlugin
from exp_assignment2.sim.plugins.drive import DiffDrivePlugin, PlanarMovePlugin
from exp_assignment2.sim.plugins.joints import (HeightPlugin, JointPositionPlugin,
                                                JointStatePlugin)
from exp_assignment2.sim.plugins.odometry import OdometryPlugin

PLUGINS = {
    'diff_drive': DiffDrivePlugin,
    'planar_move': PlanarMovePlugin,
    'joint_position': JointPositionPlugin,
    'height': HeightPlugin,
    'odometry': OdometryPlugin,
    'joint_states': JointStatePlugin,
    'camera': CameraPlugin,
}
# drives first: their commands apply before the step; publishers read after it
ORDER = ('diff_drive', 'planar_move', 'joint_position', 'height', 'odometry', 'joint_states',
         'camera')


def load_plugins(sim, model):
    """The plugins a model's world entry asks for, in application order."""
    return [PLUGINS[name](sim, model, model.plugins[name])
            for name in ORDER if name in model.plugins]

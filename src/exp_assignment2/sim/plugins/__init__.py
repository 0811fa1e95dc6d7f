"""The simulator's plugins: Gazebo's ROS plugins, one per feature.

:class:`Plugin` (in :mod:`.base`, with the whole contract) is what every
plugin subclasses. :func:`registry` maps each ``<plugin filename>`` a URDF
may name to the class that serves it; importing it needs rospy, the base
does not.
"""
from exp_assignment2.sim.plugins.base import EngineHandle, Options, Plugin, PluginError

__all__ = ['EngineHandle', 'Options', 'Plugin', 'PluginError', 'registry']


def registry():
    """``{filename: Plugin subclass}`` of the ROS plugins."""
    from exp_assignment2.sim.plugins.camera import CameraPlugin
    from exp_assignment2.sim.plugins.drive import (DiffDrivePlugin, PlanarMovePlugin,
                                                   SkidSteerDrivePlugin)
    from exp_assignment2.sim.plugins.joint_states import JointStatePublisherPlugin
    from exp_assignment2.sim.plugins.ros_control import RosControlPlugin
    return {name: cls for cls in (DiffDrivePlugin, SkidSteerDrivePlugin, PlanarMovePlugin,
                                  CameraPlugin, RosControlPlugin, JointStatePublisherPlugin)
            for name in cls.FILENAMES}

"""Which plugin libraries a Gazebo install of each ROS release has, and the
lines Gazebo logs when a model's plugin does not load (no ROS).

A ``<plugin filename>`` the simulator does not simulate is one of two things:
a library the student's Gazebo had (``libgazebo_ros_bumper.so``: ignored here,
with one warning that says so), or one no Gazebo of that release had (a typo,
a package never built): Gazebo's ``PluginT::Create`` then logs ``Failed to
load plugin F: F: cannot open shared object file: No such file or directory``
(dlopen's words) and the model loads without it, and so does it here.

The libraries are gazebo_ros_pkgs' (the ``add_library`` targets of
gazebo_plugins, gazebo_ros and gazebo_ros_control at the head of each
release's branch) and Gazebo's own, which are all called ``lib<Name>Plugin.so``.
"""
import re

# gazebo_ros_pkgs' libraries in every release (2.5, 2.8, 2.9)
COMMON = frozenset('lib%s.so' % name for name in (
    'MultiCameraPlugin', 'default_robot_hw_sim', 'gazebo_ros_api_plugin', 'gazebo_ros_control',
    'gazebo_ros_block_laser', 'gazebo_ros_bumper', 'gazebo_ros_camera',
    'gazebo_ros_camera_utils', 'gazebo_ros_depth_camera', 'gazebo_ros_diff_drive',
    'gazebo_ros_elevator', 'gazebo_ros_f3d', 'gazebo_ros_force', 'gazebo_ros_ft_sensor',
    'gazebo_ros_gpu_laser', 'gazebo_ros_hand_of_god', 'gazebo_ros_harness', 'gazebo_ros_imu',
    'gazebo_ros_imu_sensor', 'gazebo_ros_joint_pose_trajectory',
    'gazebo_ros_joint_state_publisher', 'gazebo_ros_laser', 'gazebo_ros_multicamera',
    'gazebo_ros_openni_kinect', 'gazebo_ros_p3d', 'gazebo_ros_paths_plugin',
    'gazebo_ros_planar_move', 'gazebo_ros_projector', 'gazebo_ros_prosilica',
    'gazebo_ros_range', 'gazebo_ros_skid_steer_drive', 'gazebo_ros_template',
    'gazebo_ros_tricycle_drive', 'gazebo_ros_triggered_camera',
    'gazebo_ros_triggered_multicamera', 'gazebo_ros_utils', 'gazebo_ros_vacuum_gripper',
    'gazebo_ros_video', 'vision_reconfigure'))
# what one release's branch builds and another's does not
BY_RELEASE = {
    'kinetic': COMMON | {'libgazebo_ros_joint_trajectory.so',
                         'libgazebo_ros_moveit_planning_scene.so'},
    'melodic': COMMON | {'libgazebo_ros_joint_trajectory.so',
                         'libgazebo_ros_moveit_planning_scene.so'},
    'noetic': COMMON | {'libgazebo_ros_wheel_slip.so'},
}
GAZEBO_OWN = re.compile(r'^lib[A-Za-z0-9]+Plugin\.so$')


def installed(filename, release):
    """Whether a Gazebo of ``release`` (its name) had the library ``filename``."""
    return filename in BY_RELEASE[release] or bool(GAZEBO_OWN.match(filename))


def missing(filename):
    """Gazebo's line for a library it cannot find (common/Plugin.hh, dlopen's error)."""
    return ('Failed to load plugin %s: %s: cannot open shared object file: No such file or '
            'directory' % (filename, filename))


def not_run(name, filename):
    """Gazebo's line for a plugin whose Load threw (physics/Model.cc's LoadPlugin)."""
    return ('Exception occured in the Load function of plugin with name[%s] and filename[%s]. '
            'This plugin will not run.' % (name, filename))

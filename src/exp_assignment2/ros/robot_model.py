"""The dog's robot as a node learns it from the parameter server: its
namespace and which way it turns (light: no vision, no OpenCV, so the robot's
action server does not pay for them)."""
import rospy

from exp_assignment2.sim import urdf
from exp_assignment2.sim.drives import diff_drive_turn_sign


def robot_ns():
    """The robot's namespace: the node's ``~robot_ns`` (launch argument
    ``robot_ns``), ``robot`` by default, as the original launch had it."""
    return str(rospy.get_param('~robot_ns', 'robot')).strip('/') or 'robot'


def robot_name(name):
    """``/<robot ns>/<name>``, e.g. ``robot_name('cmd_vel')`` is ``/robot/cmd_vel``."""
    return '/%s/%s' % (robot_ns(), name)


def turn_sign():
    """+1 when +angular.z turns the robot left (REP 103), -1 for the original
    robot. The simulator sets ``<robot ns>/turn_sign`` when it loads the
    robot; a node that starts first reads the same wiring from
    ``<robot ns>/robot_description`` (loaded by the launch file before any node runs)."""
    sign_param, description = robot_name('turn_sign'), robot_name('robot_description')
    sign = rospy.get_param(sign_param, None)
    if sign in (1, -1):
        return sign
    text = rospy.get_param(description, None)
    if text:
        try:
            return diff_drive_turn_sign(urdf.parse(text)) or 1
        except ValueError as exc:
            rospy.logwarn('%s: %s: %s', rospy.get_name(), description, exc)
    rospy.logwarn('%s: neither %s nor a diff-drive robot description; assuming +1 (REP 103)',
                  rospy.get_name(), sign_param)
    return 1

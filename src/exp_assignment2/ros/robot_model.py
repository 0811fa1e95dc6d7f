"""Which way the dog's robot model turns, as a node learns it from the
parameter server (light: no vision, no OpenCV, so the robot's action server
does not pay for them)."""
import rospy

from exp_assignment2.sim import urdf

TURN_SIGN_PARAM = '/robot/turn_sign'
DESCRIPTION_PARAM = '/robot/robot_description'


def turn_sign():
    """+1 when +angular.z turns the robot left (REP 103), -1 for the original
    robot. The simulator sets ``/robot/turn_sign`` when it loads the robot; a
    node that starts first reads the same wiring from ``/robot/robot_description``
    (loaded by the launch file before any node runs)."""
    sign = rospy.get_param(TURN_SIGN_PARAM, None)
    if sign in (1, -1):
        return sign
    text = rospy.get_param(DESCRIPTION_PARAM, None)
    if text:
        try:
            return urdf.diff_drive_turn_sign(urdf.parse(text))
        except ValueError as exc:
            rospy.logwarn('%s: %s: %s', rospy.get_name(), DESCRIPTION_PARAM, exc)
    rospy.logwarn('%s: neither %s nor a diff-drive robot description; assuming +1 (REP 103)',
                  rospy.get_name(), TURN_SIGN_PARAM)
    return 1

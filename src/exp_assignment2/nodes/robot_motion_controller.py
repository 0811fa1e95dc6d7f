"""``robot_motion_controller``: drives the omnidirectional MiRo to
``/target_pos``; parameters ``~kp``, ``~max_speed``, ``~tolerance``, ``~rate``."""
import rospy

from exp_assignment2.ros.miro import OmniMotionController


def main():
    rospy.init_node('robot_motion_controller')
    OmniMotionController(kp=float(rospy.get_param('~kp', 1.0)),
                         max_speed=float(rospy.get_param('~max_speed', 1.0)),
                         tolerance=float(rospy.get_param('~tolerance', 0.05)),
                         rate=float(rospy.get_param('~rate', 20.0)))
    rospy.spin()

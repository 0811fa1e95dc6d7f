"""``go_to_point_robot``: the PlanningAction server ``/robot_reaching_goal``
that turns the robot towards its goal, then drives (z ignored).

Parameters (the original's values): ``~kp_a``, ``~kp_d``, ``~dist_precision``,
``~max_linear``, ``~max_angular``, ``~goal_timeout``, ``~odom_timeout``.
"""
import rospy

from exp_assignment2.control import GoToPoint
from exp_assignment2.planning import RobotGoalController
from exp_assignment2.ros.clock import RosClock
from exp_assignment2.ros.robot_model import turn_sign
from exp_assignment2.ros.planning_server import RobotPlanningServer


def main():
    rospy.init_node('go_to_point_robot')
    controller = RobotGoalController(GoToPoint(
        dist_precision=float(rospy.get_param('~dist_precision', 0.1)),
        kp_a=float(rospy.get_param('~kp_a', 3.0)), kp_d=float(rospy.get_param('~kp_d', 0.2)),
        max_angular=float(rospy.get_param('~max_angular', 0.6)),
        max_linear=float(rospy.get_param('~max_linear', 0.6))))
    clock = RosClock()
    if not clock.wait_for_time():
        return
    RobotPlanningServer(controller, clock, turn_sign())
    rospy.spin()

"""``go_to_point_ball``: the PlanningAction server ``/reaching_goal`` that
moves the ball; the goal's z becomes its height (below 0: under the ground).

Parameters: ``~kp_d``, ``~max_speed``, ``~dist_precision``, ``~goal_timeout``,
``~odom_timeout``.
"""
import rospy

from exp_assignment2.planning import BallGoalController
from exp_assignment2.ros.clock import RosClock
from exp_assignment2.ros.planning_server import BallPlanningServer


def main():
    rospy.init_node('go_to_point_ball')
    controller = BallGoalController(kp=float(rospy.get_param('~kp_d', 0.5)),
                                    max_speed=float(rospy.get_param('~max_speed', 2.0)),
                                    precision=float(rospy.get_param('~dist_precision', 0.1)))
    clock = RosClock()
    if not clock.wait_for_time():
        return
    BallPlanningServer(controller, clock)
    rospy.spin()

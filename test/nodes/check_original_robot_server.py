#!/usr/bin/env python3
"""Does a robot server with the original's gains
(test/original/go_to_point_robot_original.py: kp_a = -3.0, kp_d = 0.2,
ub_a = 0.6, lb_a = -0.5, ub_d = 0.6), run unmodified against
robot_model:=original, take the robot to (0, 0) and then to (7, 7) through
/robot_reaching_goal, as the original's state machine asked it to?

Each goal must succeed within 120 s of ROS time and leave the robot within
0.15 m of it (the server stops at 0.1 m). With a robot that turns the other
way (robot_model:=rep103) kp_a = -3.0 turns it away from every goal: it never
arrives and this fails.
"""
import math
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus

from checks import Pose, SimpleClient, clock, wait_until
from exp_assignment2.msg import PlanningAction
from exp_assignment2.planning import make_goal

GOALS = [(0.0, 0.0), (7.0, 7.0)]
TOLERANCE = 0.15


class TestOriginalRobotServer(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_original_robot_server')
        clock().wait_for_time()
        cls.robot = Pose('/robot/odom')
        cls.client = SimpleClient('/robot_reaching_goal', PlanningAction)
        assert cls.client.wait_for_server(rospy.Duration(60)), 'no /robot_reaching_goal'
        assert wait_until(lambda: cls.robot.msg is not None, 10.0), 'no /robot/odom'

    def test_reaches_the_origin_then_the_kennel(self):
        for x, y in GOALS:
            start = rospy.get_time()
            self.client.send_goal(make_goal(x, y))
            finished = self.client.wait_for_result(rospy.Duration(120))
            rx, ry, _, _ = self.robot.xyzyaw()
            self.assertTrue(finished, 'goal (%g, %g) not reached in 120 s; the robot is at '
                            '(%.2f, %.2f)' % (x, y, rx, ry))
            self.assertEqual(self.client.get_state(), GoalStatus.SUCCEEDED)
            took = rospy.get_time() - start
            self.robot.after(rospy.get_time())       # a pose from after the result
            rx, ry, _, _ = self.robot.xyzyaw()
            error = math.hypot(rx - x, ry - y)
            print('[check_original_robot_server] goal (%g, %g): succeeded after %.1f s of ROS '
                  'time, final distance %.3f m' % (x, y, took, error))
            self.assertLess(error, TOLERANCE, 'goal (%g, %g): the robot is at (%.2f, %.2f)'
                            % (x, y, rx, ry))


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_original_robot_server', TestOriginalRobotServer)

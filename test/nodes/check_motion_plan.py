#!/usr/bin/env python3
"""A motion_plan client reaches this package's /robot_reaching_goal: the goal
it sent succeeds, with this package's feedback, and the robot is there."""
import math
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry

from checks import Watch, clock, wait_until

from exp_assignment2.msg import PlanningActionGoal


FEEDBACK = ['Fixing the yaw', 'Angle aligned', 'Reaching the goal', 'Target reached!']


class TestMotionPlan(unittest.TestCase):
    def test_a_motion_plan_goal_reaches_the_robot_server(self):
        rospy.init_node('check_motion_plan')
        clock()
        odom = Watch('/robot/odom', Odometry)
        self.assertTrue(wait_until(lambda: rospy.has_param('/send_robot_goal/result'), 100.0),
                        'the motion_plan client got no result')
        result = rospy.get_param('/send_robot_goal/result')
        self.assertEqual(result['md5'], PlanningActionGoal._md5sum)
        self.assertEqual(result['state'], 3, result)        # SUCCEEDED
        # this package's wording, in order; the last ('Target reached!') may be
        # lost: feedback and result are two topics, and a SimpleActionClient
        # drops feedback that comes after its goal's result (so did Gazebo's)
        heard = result['feedback']
        self.assertEqual(heard, FEEDBACK[:len(heard)], result)
        self.assertGreaterEqual(len(heard), 3, result)
        where = odom.next(10.0).pose.pose.position
        self.assertLess(math.hypot(where.x + 3.0, where.y - 5.0), 0.5, (where.x, where.y))


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_motion_plan', TestMotionPlan)

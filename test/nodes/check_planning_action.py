#!/usr/bin/env python3
"""A real SimpleActionServer and SimpleActionClient exchange PlanningAction
goals over ROS topics: goal, feedback, result, and preemption."""
import threading
import unittest

import actionlib
import rospy
import rostest
from exp_assignment2.msg import PlanningAction, PlanningFeedback, PlanningGoal, PlanningResult


class EchoServer(object):
    """Reports 'Reaching the goal' until done or preempted; echoes the pose."""

    def __init__(self):
        self.release = threading.Event()
        self.server = actionlib.SimpleActionServer('/test_planning', PlanningAction,
                                                   self.execute, auto_start=False)
        self.server.start()

    def execute(self, goal):
        fb = PlanningFeedback(stat='Reaching the goal', position=goal.target_pose.pose)
        for _ in range(1000):
            if self.server.is_preempt_requested():
                self.server.set_preempted()
                return
            self.server.publish_feedback(fb)
            if self.release.wait(0.01):
                break
        self.server.publish_feedback(PlanningFeedback(stat='Target reached!'))
        self.server.set_succeeded(PlanningResult())


class TestPlanningAction(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_planning_action')
        cls.echo = EchoServer()
        cls.client = actionlib.SimpleActionClient('/test_planning', PlanningAction)
        assert cls.client.wait_for_server(rospy.Duration(10))

    def goal(self, x, y):
        goal = PlanningGoal()
        goal.target_pose.header.frame_id = 'odom'
        goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = x, y
        return goal

    def test_goal_feedback_result(self):
        feedback = []
        self.echo.release.clear()
        self.client.send_goal(self.goal(1.5, -2.0), feedback_cb=feedback.append)
        deadline = rospy.Time.now() + rospy.Duration(5)
        while not feedback and rospy.Time.now() < deadline:
            rospy.sleep(0.01)
        self.echo.release.set()
        self.assertTrue(self.client.wait_for_result(rospy.Duration(10)))
        self.assertEqual(self.client.get_state(), actionlib.GoalStatus.SUCCEEDED)
        self.assertIsInstance(self.client.get_result(), PlanningResult)
        self.assertEqual(feedback[0].stat, 'Reaching the goal')
        self.assertAlmostEqual(feedback[0].position.position.x, 1.5)
        self.assertAlmostEqual(feedback[0].position.position.y, -2.0)

    def test_preemption(self):
        self.echo.release.clear()
        self.client.send_goal(self.goal(3.0, 3.0))
        rospy.sleep(0.2)
        self.client.cancel_goal()
        self.assertTrue(self.client.wait_for_result(rospy.Duration(10)))
        self.assertEqual(self.client.get_state(), actionlib.GoalStatus.PREEMPTED)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_planning_action', TestPlanningAction)

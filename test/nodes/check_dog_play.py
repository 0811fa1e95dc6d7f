#!/usr/bin/env python3
"""Scenario A: from a start with the ball in view the dog plays, comes close,
sweeps its head, shrugs off bad input, and returns to NORMAL when the ball hides.
Steps run in order (test_1 ... test_4) on one running system."""
import math
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from std_msgs.msg import String

from dog_checks import DogObserver, wait_until
from exp_assignment2.msg import PlanningAction, PlanningGoal


def goal(x, y, z=0.0):
    g = PlanningGoal()
    g.target_pose.pose.position.x, g.target_pose.pose.position.y = x, y
    g.target_pose.pose.position.z = z
    return g


class TestDogPlay(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_dog_play')
        cls.dog = DogObserver()
        cls.command = rospy.Publisher('/ball/command', String, queue_size=10)
        cls.ball = actionlib.SimpleActionClient('/reaching_goal', PlanningAction)
        cls.robot = actionlib.SimpleActionClient('/robot_reaching_goal', PlanningAction)
        assert cls.ball.wait_for_server(rospy.Duration(60))
        assert cls.robot.wait_for_server(rospy.Duration(60))
        cls.start = rospy.Time.now()

    def test_1_enters_play_within_20s_and_comes_within_1_5m(self):
        self.assertTrue(wait_until(lambda: self.dog.state() == 'PLAY', 20.0),
                        'states seen: %s' % [s for _, s in self.dog.states])
        entered = [t for t, s in self.dog.states if s == 'PLAY'][0]
        self.assertLessEqual(entered.to_sec(), 20.0)
        self.assertTrue(wait_until(lambda: self.dog.ball_distance() < 1.5, 40.0),
                        'robot-ball distance %.2f m' % self.dog.ball_distance())

    def test_2_head_sweeps_to_plus_and_minus_45_degrees(self):
        tol = math.radians(5)
        self.assertTrue(wait_until(lambda: self.dog.head_reached(math.radians(45), tol)
                                   and self.dog.head_reached(math.radians(-45), tol), 60.0),
                        'head range seen: %.2f..%.2f rad' % (min(self.dog.head_positions),
                                                             max(self.dog.head_positions)))

    def test_3_bad_input_is_rejected_and_the_system_keeps_running(self):
        for text in ('go to 100 0', 'jump', 'go to nan 1', '', 'go to 1'):
            self.command.publish(String(text))
        for client, bad in ((self.ball, goal(20.0, 0.0)), (self.robot, goal(0.0, -9.0)),
                            (self.robot, goal(float('nan'), 1.0))):
            client.send_goal(bad)
            self.assertTrue(client.wait_for_result(rospy.Duration(10)))
            self.assertEqual(client.get_state(), GoalStatus.ABORTED)
            self.assertIn('arena' if not math.isnan(bad.target_pose.pose.position.x)
                          else 'finite', client.get_goal_status_text())
        # still working: the ball server moves the ball to a valid goal
        b = self.dog.ball.msg.pose.pose.position
        self.ball.send_goal(goal(b.x, b.y))
        self.assertTrue(self.ball.wait_for_result(rospy.Duration(30)))
        self.assertEqual(self.ball.get_state(), GoalStatus.SUCCEEDED)
        self.assertIn(self.dog.state(), ('PLAY', 'NORMAL'))

    def test_4_hiding_the_ball_brings_normal_within_the_timeout(self):
        self.assertTrue(wait_until(lambda: self.dog.state() == 'PLAY', 30.0))
        hidden_at = rospy.Time.now()
        self.command.publish(String('hide'))
        lost_timeout = 2 * math.pi / 0.5
        self.assertTrue(wait_until(lambda: self.dog.state() == 'NORMAL', lost_timeout + 5.0))
        took = ([t for t, s in self.dog.states if s == 'NORMAL'][-1] - hidden_at).to_sec()
        rospy.loginfo('NORMAL %.1f s after hiding the ball', took)
        self.assertLessEqual(took, lost_timeout + 2.0)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_dog_play', TestDogPlay)

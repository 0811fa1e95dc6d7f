#!/usr/bin/env python3
"""robot_to_ball.py alone: the dog comes to the ball, and follows it when
the ball is moved away."""
import unittest

import rospy
import rostest
from std_msgs.msg import String

from checks import DogObserver, clock, wait_for_subscribers, wait_until


class TestRobotToBall(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_robot_to_ball')
        clock()
        cls.dog = DogObserver()
        cls.command = rospy.Publisher('/ball/command', String, queue_size=10)

    def test_follows_the_ball(self):
        self.assertTrue(wait_until(lambda: self.dog.ball_distance() < 1.5, 30.0),
                        'distance %.2f m' % self.dog.ball_distance())
        wait_for_subscribers(self.command)
        self.command.publish(String('go to -2 4'))
        self.assertTrue(wait_until(lambda: self.dog.ball_distance() > 2.0, 5.0))
        self.assertTrue(wait_until(lambda: self.dog.ball_distance() < 1.5, 60.0),
                        'distance %.2f m' % self.dog.ball_distance())


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_robot_to_ball', TestRobotToBall)

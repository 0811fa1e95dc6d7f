#!/usr/bin/env python3
"""Scenario A forced to sleep: the dog goes to its kennel at (7, 7),
ignoring the ball it starts next to, rests 14 s, and wakes up to NORMAL."""
import math
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus

from checks import DogObserver, Watch, clock, wait_until
from exp_assignment2.msg import PlanningActionResult

KENNEL = (7.0, 7.0)


class TestDogSleep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_dog_sleep')
        clock()
        cls.dog = DogObserver()
        cls.results = Watch('/robot_reaching_goal/result', PlanningActionResult, keep=True)

    def reached(self):
        """The robot goals that succeeded (the one to the kennel)."""
        return [r for r in self.results.all if r.status.status == GoalStatus.SUCCEEDED]

    def kennel_distance(self):
        if self.dog.robot.msg is None:
            return float('inf')
        x, y, _, _ = self.dog.robot.xyzyaw()
        return math.hypot(x - KENNEL[0], y - KENNEL[1])

    def test_goes_home_sleeps_14s_and_wakes(self):
        self.assertTrue(wait_until(lambda: self.dog.state() == 'SLEEP', 10.0))
        self.assertTrue(wait_until(lambda: self.reached(), 90.0),
                        'still %.2f m from the kennel' % self.kennel_distance())
        arrived = self.reached()[0].header.stamp.to_sec()
        self.assertLess(self.kennel_distance(), 0.15)
        self.assertNotIn('PLAY', [s for _, s in self.dog.states], 'the ball is ignored')

        def woke():
            return [t for t in self.dog.entered('NORMAL') if t > arrived]
        self.assertTrue(wait_until(woke, 20.0))
        rested = woke()[0] - arrived
        rospy.loginfo('rested %.2f s at the kennel', rested)
        self.assertAlmostEqual(rested, 14.0, delta=0.1)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_dog_sleep', TestDogSleep)

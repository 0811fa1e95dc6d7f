#!/usr/bin/env python3
"""Scenario A: in SLEEP the dog goes to its kennel at (7, 7), ignoring the ball
it starts next to, rests, and wakes up to NORMAL."""
import math
import unittest

import rospy
import rostest

from dog_checks import DogObserver, wait_until

HOME = (7.0, 7.0)


class TestDogSleep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_dog_sleep')
        cls.dog = DogObserver()

    def home_distance(self):
        if self.dog.robot.msg is None:
            return float('inf')
        x, y = self.dog.robot_xy()
        return math.hypot(x - HOME[0], y - HOME[1])

    def test_goes_home_sleeps_and_wakes(self):
        self.assertTrue(wait_until(lambda: self.dog.state() == 'SLEEP', 10.0))
        self.assertTrue(wait_until(lambda: self.home_distance() < 0.5, 90.0),
                        'still %.2f m from home' % self.home_distance())
        self.assertNotIn('PLAY', [s for _, s in self.dog.states], 'the ball is ignored')
        arrived = rospy.Time.now()
        def woke():
            return [t for t, s in self.dog.states if s == 'NORMAL' and t > arrived]
        # with sleep_probability 1 NORMAL lasts a moment before the next SLEEP
        self.assertTrue(wait_until(woke, 30.0))  # last 0.4 m + 14 s asleep
        rested = (woke()[0] - arrived).to_sec()
        rospy.loginfo('rested %.1f s at home', rested)
        self.assertGreater(rested, 10.0)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_dog_sleep', TestDogSleep)

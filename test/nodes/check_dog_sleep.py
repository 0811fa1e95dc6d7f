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

    def rest_began(self, after):
        """When the state machine began its rest (its stamps), after ``after``."""
        return [m.header.stamp.to_sec() for m in self.dog.rosout.lines('SLEEP: resting',
                                                                       node='/state_machine')
                if m.header.stamp.to_sec() > after]

    def kennel_distance(self):
        if self.dog.robot.msg is None:
            return float('inf')
        x, y, _, _ = self.dog.robot.xyzyaw()
        return math.hypot(x - KENNEL[0], y - KENNEL[1])

    def test_goes_home_sleeps_14s_and_wakes(self):
        self.assertTrue(wait_until(lambda: self.dog.entered('SLEEP'), 30.0))
        self.assertTrue(wait_until(lambda: self.reached(), 120.0),
                        'still %.2f m from the kennel' % self.kennel_distance())
        arrived = self.reached()[0].header.stamp.to_sec()
        # where it stopped: odometry stamped from the arrival on (on a loaded
        # machine the latest one here may still be from before it)
        self.assertTrue(wait_until(lambda: self.dog.robot.msg.header.stamp.to_sec() >= arrived,
                                   10.0), 'no odometry after the arrival')
        self.assertLess(self.kennel_distance(), 0.15)
        self.assertNotIn('PLAY', [s for _, s in self.dog.states], 'the ball is ignored')
        # the state machine's own stamps (its rest, then NORMAL, which with
        # sleep_probability 1 lasts 0.01 s before the next SLEEP), not the times
        # they reached this checker: at real_time_factor 0 a message's wall
        # latency is many simulated seconds
        self.assertTrue(wait_until(lambda: self.rest_began(arrived), 30.0),
                        'no rest logged after the kennel was reached')
        began = self.rest_began(arrived)[0]
        self.assertTrue(wait_until(lambda: self.dog.logged('NORMAL', began), 40.0),
                        'states seen: %s' % self.dog.states)
        rested = self.dog.logged('NORMAL', began)[0] - began
        rospy.loginfo('rested %.2f s at the kennel, from %.2f s after the arrival',
                      rested, began - arrived)
        # never shorter (the rest's line comes before its wait); longer by
        # whatever keeps the state machine off its CPU as it wakes and logs:
        # at 20x, 0.35 s of wall time is the 7 s allowed here. The stamps are
        # floats (64.1 - 50.1 is 13.999999999999993): half a step of slack
        self.assertTrue(14.0 - 0.005 <= rested <= 21.0, rested)
        self.assertTrue(wait_until(lambda: self.dog.entered('NORMAL', arrived), 10.0),
                        'NORMAL was logged but never reached /robot/state\'s subscribers')


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_dog_sleep', TestDogSleep)

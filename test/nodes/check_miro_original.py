#!/usr/bin/env python3
"""A user's own MiRo nodes on miro_world.launch: they find /odom, /cmd_vel
and the parameters they expect, and MiRo reaches their targets (home first,
then random points) one after another."""
import math
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry

from checks import Watch, clock, wait_until


class TestMiroOriginal(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_miro_original')
        clock()
        cls.odom = Watch('/odom', Odometry)
        cls.arrivals = []

    def arrival(self):
        """The /all parameter of a new arrival ([target x, y, x, y, number]), if any."""
        report = rospy.get_param('/all', None)
        if report and (not self.arrivals or report[4] != self.arrivals[-1][4]):
            self.arrivals.append(report)
        return len(self.arrivals)

    def test_miro_goes_home_then_wanders_arriving_each_time(self):
        self.odom.next(30.0)
        self.assertTrue(wait_until(lambda: self.arrival() >= 3, 300.0),
                        'arrivals: %s' % self.arrivals)
        home = self.arrivals[0]
        self.assertEqual(home[:2], [3, 3])
        for target_x, target_y, x, y, number in self.arrivals:
            rospy.loginfo('arrival %d: target (%d, %d), MiRo at (%.2f, %.2f)',
                          number, target_x, target_y, x, y)
            self.assertLess(math.hypot(target_x - x, target_y - y), 0.05)
        self.assertIn(rospy.get_param('/state'), ('NORMAL', 'SLEEP STATE'))


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_miro_original', TestMiroOriginal)

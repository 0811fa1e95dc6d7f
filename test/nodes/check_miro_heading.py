#!/usr/bin/env python3
"""MiRo turned by {angular: {z: 1.5}} on /cmd_vel (to about 150 degrees)
still reaches 'go to 6 2', then 'go to 1 8': the motion controller commands
in MiRo's frame, whatever its heading."""
import math
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from std_msgs.msg import Float64MultiArray, String

from checks import Pose, Watch, clock, wait_for_subscribers, wait_until
from system_checks import wait_for_graph

TOLERANCE = 0.05


class TestMiroHeading(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_miro_heading')
        clock()
        cls.odom = Pose('/odom')
        cls.arrivals = Watch('/arrival', Float64MultiArray, keep=True)
        cls.cmd = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
        cls.command = rospy.Publisher('/command', String, queue_size=10)
        wait_for_subscribers(cls.cmd)
        wait_for_subscribers(cls.command)
        # the order goes /command -> grounding -> /target_pos -> motion controller
        wait_for_graph('/target_pos', '/robot_motion_controller')

    def yaw(self):
        return math.degrees(self.odom.xyzyaw()[3])

    def turn(self, rate, degrees, seconds=20.0):
        """Turn at ``rate`` until the heading has changed by ``degrees`` (at
        most ``seconds``): at real_time_factor 0 a checker kept off its CPU
        misses beats of its 20 Hz and the drive's command timeout stops the
        turn in between, so an angle is waited for rather than a duration."""
        twist = Twist()
        twist.angular.z = rate
        self.odom.next()
        start = self.yaw()
        end = rospy.get_time() + seconds

        def turned():
            return abs(math.atan2(math.sin(math.radians(self.yaw() - start)),
                                  math.cos(math.radians(self.yaw() - start)))) >= math.radians(
                degrees)
        while rospy.get_time() < end and not turned():
            self.cmd.publish(twist)
            clock().sleep(0.05)
        clock().sleep(1.0)          # the drive's cmd_timeout stops the turn

    def go_to(self, x, y):
        before = len(self.arrivals.all)
        self.command.publish(String('go to %d %d' % (x, y)))

        def arrived():
            return [a.data for a in self.arrivals.all[before:] if tuple(a.data[:2]) == (x, y)]
        self.assertTrue(wait_until(arrived, 60.0), 'MiRo at %.2f, %.2f, never at (%d, %d)'
                        % (self.odom.xyzyaw()[:2] + (x, y)))
        a = arrived()[0]
        self.assertLessEqual(math.hypot(a[2] - x, a[3] - y), TOLERANCE)

    def test_miro_reaches_its_targets_whatever_its_heading(self):
        self.turn(1.5, 150.0)
        self.odom.next()
        yaw = math.degrees(self.odom.xyzyaw()[3])
        rospy.loginfo('MiRo turned to %.0f degrees', yaw)
        self.assertGreater(abs(yaw), 45.0, 'the turn did not happen')
        self.go_to(6, 2)
        self.turn(-1.0, 100.0)
        self.go_to(1, 8)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_miro_heading', TestMiroHeading)

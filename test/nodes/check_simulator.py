#!/usr/bin/env python3
"""The simulator does what Gazebo did: camera content, diff drive by REP 103,
head control, reset, a clock faster than the wall, and bad commands ignored."""
import math
import threading
import time
import unittest

import cv2
import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import CompressedImage, JointState
from std_msgs.msg import Float64
from std_srvs.srv import Empty, SetBool

from exp_assignment2.simulator import yaw_of

SPAWN = (-5.0, 7.0, math.pi)


def green_pixels(msg):
    img = cv2.imdecode(np.frombuffer(msg.data, np.uint8), cv2.IMREAD_COLOR)
    hsv = cv2.cvtColor(img, cv2.COLOR_BGR2HSV)
    return int(np.count_nonzero(cv2.inRange(hsv, (50, 50, 20), (70, 255, 255))))


class Latest(object):
    def __init__(self, topic, cls):
        self.msg, self.event = None, threading.Event()
        rospy.Subscriber(topic, cls, self._cb, queue_size=1)

    def _cb(self, msg):
        self.msg = msg
        self.event.set()

    def after(self, stamp, timeout=10.0):
        """The first message stamped after ``stamp`` (ROS time)."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            msg = self.msg
            if msg is not None and msg.header.stamp > stamp:
                return msg
            self.event.clear()
            self.event.wait(0.05)
        raise AssertionError('no message after %s' % stamp.to_sec())


class TestSimulator(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_simulator')
        for srv in ('/gazebo/reset_world', '/ball/set_visible'):
            rospy.wait_for_service(srv, timeout=30)
        cls.reset = rospy.ServiceProxy('/gazebo/reset_world', Empty)
        cls.pause = rospy.ServiceProxy('/gazebo/pause_physics', Empty)
        cls.unpause = rospy.ServiceProxy('/gazebo/unpause_physics', Empty)
        cls.visible = rospy.ServiceProxy('/ball/set_visible', SetBool)
        cls.cmd = rospy.Publisher('/robot/cmd_vel', Twist, queue_size=1)
        cls.head = rospy.Publisher('/robot/joint_position_controller/command', Float64,
                                   queue_size=1)
        cls.odom = Latest('/robot/odom', Odometry)
        cls.joints = Latest('/robot/joint_states', JointState)
        cls.image = Latest('/robot/camera1/image_raw/compressed', CompressedImage)
        assert cls.odom.event.wait(30) and cls.image.event.wait(30)

    def setUp(self):
        self.reset()
        self.visible(True)
        rospy.sleep(0.2)

    def drive(self, linear, angular, seconds):
        """Publish a command at 20 Hz of simulated time for ``seconds``."""
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        end = rospy.Time.now() + rospy.Duration(seconds)
        while rospy.Time.now() < end:
            self.cmd.publish(twist)
            rospy.sleep(0.05)

    def pose(self):
        msg = self.odom.after(rospy.Time.now())
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        return p.x, p.y, yaw_of((q.x, q.y, q.z, q.w))

    def test_camera_sees_the_ball_and_not_after_it_is_hidden(self):
        facing = green_pixels(self.image.after(rospy.Time.now()))
        self.assertGreater(facing, 1000, 'the ball at (-7, 6) should fill part of the view')
        self.assertTrue(self.visible(False).success)
        hidden = green_pixels(self.image.after(rospy.Time.now() + rospy.Duration(0.1)))
        self.assertEqual(hidden, 0)
        self.visible(True)
        shown = green_pixels(self.image.after(rospy.Time.now() + rospy.Duration(0.1)))
        self.assertGreater(shown, 1000)

    def test_positive_angular_z_turns_counter_clockwise(self):
        _, _, yaw0 = self.pose()
        self.drive(0.0, 0.5, 1.0)
        _, _, yaw1 = self.pose()
        turned = math.atan2(math.sin(yaw1 - yaw0), math.cos(yaw1 - yaw0))
        self.assertGreater(turned, 0.25)

    def test_forward_command_moves_along_the_heading(self):
        x0, y0, yaw0 = self.pose()
        self.drive(0.4, 0.0, 2.0)
        x1, y1, _ = self.pose()
        along = (x1 - x0) * math.cos(yaw0) + (y1 - y0) * math.sin(yaw0)
        across = -(x1 - x0) * math.sin(yaw0) + (y1 - y0) * math.cos(yaw0)
        self.assertGreater(along, 0.5)
        self.assertLess(abs(across), 0.1)
        twist = self.odom.msg.twist.twist
        self.assertGreater(twist.linear.x, 0.3, 'odom twist is in the child frame')

    def test_stale_command_stops_the_robot(self):
        self.drive(0.4, 0.0, 0.5)
        rospy.sleep(1.5)       # no commands: the 0.5 s timeout stops the wheels
        x0, y0, _ = self.pose()
        rospy.sleep(1.0)
        x1, y1, _ = self.pose()
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 0.02)

    def test_nan_command_is_ignored(self):
        x0, y0, _ = self.pose()
        twist = Twist()
        twist.linear.x = float('nan')
        twist.angular.z = float('inf')
        for _ in range(5):
            self.cmd.publish(twist)
            rospy.sleep(0.1)
        x1, y1, _ = self.pose()
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 0.02)
        self.test_positive_angular_z_turns_counter_clockwise()   # still obeys

    def test_head_follows_its_command_and_is_clamped(self):
        def head_position(after):
            msg = self.joints.after(after)
            return msg.position[msg.name.index('head_joint')]
        self.head.publish(Float64(0.6))
        rospy.sleep(1.5)
        self.assertAlmostEqual(head_position(rospy.Time.now()), 0.6, delta=0.03)
        self.head.publish(Float64(3.0))
        rospy.sleep(2.0)
        self.assertAlmostEqual(head_position(rospy.Time.now()), math.pi / 2, delta=0.03)
        self.head.publish(Float64(0.0))
        rospy.sleep(1.5)

    def test_reset_puts_models_back(self):
        self.drive(0.5, 0.3, 2.0)
        x, y, _ = self.pose()
        self.assertGreater(math.hypot(x - SPAWN[0], y - SPAWN[1]), 0.3)
        self.reset()
        x, y, yaw = self.pose()
        self.assertLess(math.hypot(x - SPAWN[0], y - SPAWN[1]), 0.02)
        self.assertLess(abs(math.atan2(math.sin(yaw - SPAWN[2]), math.cos(yaw - SPAWN[2]))), 0.02)

    def test_pause_stops_the_clock(self):
        self.pause()
        try:
            t0 = rospy.wait_for_message('/clock', Clock, timeout=5).clock
            time.sleep(0.3)
            t1 = rospy.Time.now()
            self.assertLess((t1 - t0).to_sec(), 0.05)
        except rospy.ROSException:
            pass   # no /clock at all while paused is also a stopped clock
        finally:
            self.unpause()

    def test_clock_runs_faster_than_wall_time(self):
        t0, w0 = rospy.Time.now(), time.monotonic()
        time.sleep(2.0)
        ratio = (rospy.Time.now() - t0).to_sec() / (time.monotonic() - w0)
        rospy.loginfo('simulated / wall time: %.2f', ratio)
        self.assertGreater(ratio, 1.0)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_simulator', TestSimulator)

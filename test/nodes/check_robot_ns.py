#!/usr/bin/env python3
"""robot_ns:=robot2: the simulator, the controllers, robot_state_publisher and
the package's own nodes all use /robot2; nothing is left on /robot."""
import unittest

import rosgraph
import rospy
import rostest
import tf2_ros
from nav_msgs.msg import Odometry
from sensor_msgs.msg import CompressedImage, JointState
from std_msgs.msg import Float64, String

from checks import Watch, clock, wait_for_subscribers, wait_until


class TestRobotNamespace(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_robot_ns')
        clock()
        cls.odom = Watch('/robot2/odom', Odometry)
        cls.image = Watch('/robot2/camera1/image_raw/compressed', CompressedImage)
        cls.joints = Watch('/robot2/joint_states', JointState)
        cls.states = Watch('/robot2/state', String, keep=True)
        cls.tf = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf)

    def test_every_robot_topic_is_under_robot2(self):
        self.odom.next(30.0)
        self.image.next(30.0)
        self.joints.next(30.0)
        topics = [t for t, _ in rosgraph.Master('/check_robot_ns').getPublishedTopics('')]
        self.assertEqual([t for t in topics if t.startswith('/robot/')], [], topics)
        self.assertEqual(rospy.get_param('/robot2/turn_sign'), 1)

    def test_the_head_controller_and_tf_are_in_robot2(self):
        head = rospy.Publisher('/robot2/joint_position_controller/command', Float64,
                               queue_size=1, latch=True)
        wait_for_subscribers(head)
        self.assertTrue(wait_until(lambda: self.tf.can_transform(
            'odom', 'camera_link', rospy.Time(0)), 20.0))

    def test_the_dog_sees_the_ball_and_plays(self):
        self.assertTrue(wait_until(lambda: any(m.data == 'PLAY' for m in self.states.all),
                                   60.0), [m.data for m in self.states.all])


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_robot_ns', TestRobotNamespace)

#!/usr/bin/env python3
"""A URDF spawned into the running simulator brings its own plugins, as in
Gazebo: its diff drive, camera and ros_control run at the rates and with the
names its <gazebo> tags give; it can be deleted; bad spawns are refused."""
import math
import os
import unittest

import rospkg
import rospy
import rostest
from gazebo_msgs.srv import DeleteModel, GetModelState, SpawnModel
from geometry_msgs.msg import Pose, Quaternion, Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import CameraInfo, Image, JointState
from std_msgs.msg import Float64

from checks import Rosout, Watch, clock, eventually, wait_for_subscribers, wait_until
from exp_assignment2.geometry import yaw_of

FIXTURES = os.path.join(rospkg.RosPack().get_path('exp_assignment2'), 'test', 'fixtures')


def rate(watch, seconds=4.0):
    """Messages published per second of simulated time, from the stamps and
    sequence numbers of those that arrive in ``seconds``: late delivery, or a
    message a loaded machine drops on its way, does not count as a lower rate."""
    start = len(watch.all)

    def spanned():        # what arrives after now, over ``seconds`` of its own stamps
        got = watch.all[start:]
        return len(got) >= 2 and got[-1].header.stamp.to_sec() - got[0].header.stamp.to_sec() \
            >= seconds
    assert wait_until(spanned, 10.0 * seconds), '%s: not %g s of messages' % (watch.topic,
                                                                             seconds)
    first, last = watch.all[start].header, watch.all[-1].header
    return (last.seq - first.seq) / (last.stamp.to_sec() - first.stamp.to_sec())


class TestSpawn(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_spawn')
        clock()
        for name in ('spawn_urdf_model', 'delete_model', 'get_model_state'):
            rospy.wait_for_service('/gazebo/' + name, timeout=30)
        cls.spawn = rospy.ServiceProxy('/gazebo/spawn_urdf_model', SpawnModel)
        cls.delete = rospy.ServiceProxy('/gazebo/delete_model', DeleteModel)
        cls.state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        with open(os.path.join(FIXTURES, 'spawned_robot.urdf')) as f:
            cls.urdf = f.read()
        cls.rosout = Rosout()
        cls.rosout.connected('/gazebo')   # its warnings must reach us
        cls.odom = Watch('/spawned/odom', Odometry, keep=True)
        cls.image = Watch('/spawned/front/image_raw', Image, keep=True)
        cls.info = Watch('/spawned/front/camera_info', CameraInfo)
        cls.joints = Watch('/spawned/joint_states', JointState, keep=True)
        cls.cmd = rospy.Publisher('/spawned/cmd_vel', Twist, queue_size=1)
        cls.head = rospy.Publisher('/spawned/joint_head_controller/command', Float64,
                                   queue_size=1)
        pose = Pose()
        pose.position.x, pose.position.y, pose.position.z = 2.0, -3.0, 0.07
        pose.orientation = Quaternion(0, 0, math.sin(0.25), math.cos(0.25))   # yaw 0.5
        cls.answer = cls.spawn('spawned', cls.urdf, 'spawned', pose, 'world')

    def test_1_it_spawns_where_asked_with_its_plugins(self):
        self.assertTrue(self.answer.success, self.answer.status_message)
        msg = self.odom.next(10.0)
        p = msg.pose.pose.position
        self.assertAlmostEqual(p.x, 2.0, delta=0.05)
        self.assertAlmostEqual(p.y, -3.0, delta=0.05)
        q = msg.pose.pose.orientation
        self.assertAlmostEqual(yaw_of((q.x, q.y, q.z, q.w)), 0.5, delta=0.02)
        self.assertEqual((msg.header.frame_id, msg.child_frame_id), ('odom', 'base_link'))
        # /rosout reaches this checker some wall time after the answer
        eventually(lambda: self.rosout.lines('libgazebo_ros_bumper.so', Log.WARN)
                   and self.rosout.lines('not_a_joint_controller', Log.WARN))
        warnings = [m.msg for m in self.rosout.lines('libgazebo_ros_bumper.so', Log.WARN)]
        self.assertEqual(len(warnings), 1, warnings)
        controller = self.rosout.lines('not_a_joint_controller', Log.WARN)
        self.assertEqual(len(controller), 1, [m.msg for m in controller])
        self.assertIn("joint 'elbow' is not a joint of model spawned", controller[0].msg)

    def test_2_rates_and_sizes_are_the_urdf_s(self):
        odom = rate(self.odom)
        rospy.loginfo('spawned: odometry at %.1f Hz of simulated time', odom)
        self.assertAlmostEqual(odom, 25.0, delta=1.5)
        image = self.image.next(10.0)
        self.assertEqual((image.width, image.height, image.encoding), (160, 120, 'rgb8'))
        self.assertEqual(len(image.data), 160 * 120 * 3)
        self.assertEqual(image.header.frame_id, 'cam_link')
        camera = rate(self.image)
        rospy.loginfo('spawned: camera at %.1f Hz of simulated time', camera)
        self.assertAlmostEqual(camera, 10.0, delta=1.0)
        info = self.info.next()
        self.assertAlmostEqual(info.K[0], 160 / (2 * math.tan(0.5)), places=4)
        joints = rate(self.joints)
        self.assertAlmostEqual(joints, 40.0, delta=2.5)
        self.assertIn('neck', self.joints.msg.name)

    def test_3_the_yaml_s_controller_moves_the_head(self):
        wait_for_subscribers(self.head)
        self.head.publish(Float64(0.6))

        def at_target():
            msg = self.joints.msg
            return msg is not None and abs(msg.position[msg.name.index('neck')] - 0.6) < 0.02
        self.assertTrue(wait_until(at_target, 5.0), self.joints.msg)

    def test_4_angular_z_turns_the_way_the_wheels_say(self):
        wait_for_subscribers(self.cmd)

        def yaw(msg):
            q = msg.pose.pose.orientation
            return yaw_of((q.x, q.y, q.z, q.w))

        def turned():
            return math.atan2(math.sin(yaw(self.odom.msg) - yaw0),
                              math.cos(yaw(self.odom.msg) - yaw0))
        yaw0 = yaw(self.odom.next())
        twist = Twist()
        twist.angular.z = 0.8
        # until it has turned (either way), at most 10 s: at real_time_factor 0
        # a checker kept off its CPU misses beats of its 20 Hz commands, and
        # the drive's command timeout stops the turn in between
        end = rospy.get_time() + 10.0
        while rospy.get_time() < end and abs(turned()) < 0.6:
            self.cmd.publish(twist)
            clock().sleep(0.05)
        self.odom.next()
        angle = turned()
        rospy.loginfo('spawned: +0.8 rad/s turned it by %+.2f rad', angle)
        self.assertGreater(angle, 0.4, 'leftJoint is on the left: +angular.z turns left')

    def test_5_bad_spawns_are_refused_and_change_nothing(self):
        pose = Pose()
        pose.orientation.w = 1.0
        for name, xml, why in (('spawned', self.urdf, 'exists already'),
                               ('broken', '<robot name="x"><link', 'not a valid URDF'),
                               ('nolink', '<robot name="x"/>', 'has no link')):
            answer = self.spawn(name, xml, '', pose, '')
            self.assertFalse(answer.success)
            self.assertIn(why, answer.status_message)
        pose.position.x = float('nan')
        answer = self.spawn('nan', self.urdf, 'nan', pose, '')
        self.assertFalse(answer.success)
        self.assertIn('not finite', answer.status_message)
        answer = self.spawn('rel', self.urdf, 'rel', Pose(), 'no_such_model')
        self.assertFalse(answer.success)
        self.assertIn("no model or link named 'no_such_model'", answer.status_message)
        for name in ('broken', 'nolink', 'nan', 'rel'):
            self.assertFalse(self.state(name, '').success)

    def test_6_deleted_it_is_gone(self):
        self.assertTrue(self.delete('spawned').success)
        self.assertFalse(self.state('spawned', '').success)
        count = self.odom.count
        clock().sleep(1.0)
        self.assertLessEqual(self.odom.count - count, 1)
        self.assertFalse(self.delete('spawned').success)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_spawn', TestSpawn)

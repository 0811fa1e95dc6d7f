#!/usr/bin/env python3
"""A user's controller YAML loaded under /robot after the simulator started:
its renamed controller moves the head, its joint-state rate is used, bad
entries get one warning each, and the default controller keeps working."""
import unittest

import rospy
import rostest
from controller_manager_msgs.srv import ListControllers
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64

from checks import Rosout, Watch, clock, wait_for_subscribers, wait_until

USER_YAML = {
    'joint_state_controller': {'type': 'joint_state_controller/JointStateController',
                               'publish_rate': 20},
    'joint_head_controller': {'type': 'effort_controllers/JointPositionController',
                              'joint': 'head_joint', 'pid': {'p': 100.0, 'i': 0.1, 'd': 1.0}},
    'arm_controller': {'type': 'position_controllers/JointPositionController',
                       'joint': 'arm_joint_01'},
    'gripper_controller': {'type': 'effort_controllers/GripperActionController',
                           'joint': 'head_joint'},
}


class TestControllers(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_controllers')
        clock()
        cls.rosout = Rosout()
        cls.rosout.connected('/gazebo')   # its warnings must reach us
        cls.joints = Watch('/robot/joint_states', JointState, keep=True)
        cls.joints.next(30.0)
        for name, config in USER_YAML.items():          # what rosparam load does
            rospy.set_param('/robot/' + name, config)

    def head(self):
        msg = self.joints.msg
        return msg.position[msg.name.index('head_joint')]

    def command(self, controller, value):
        pub = rospy.Publisher('/robot/%s/command' % controller, Float64, queue_size=1,
                              latch=True)
        wait_for_subscribers(pub)
        pub.publish(Float64(value))
        self.assertTrue(wait_until(lambda: abs(self.head() - value) < 0.03, 5.0),
                        '%s: head at %.3f, not %.3f' % (controller, self.head(), value))

    def test_the_renamed_controller_and_the_default_one_move_the_head(self):
        self.command('joint_head_controller', 0.7)
        self.command('joint_position_controller', -0.4)

    def test_the_yaml_s_joint_state_rate_is_used(self):
        clock().sleep(1.0)                           # the new rate in force
        start = len(self.joints.all)
        clock().sleep(4.0)
        stamps = [m.header.stamp.to_sec() for m in self.joints.all[start:]]
        rate = (len(stamps) - 1) / (stamps[-1] - stamps[0])
        rospy.loginfo('joint states at %.1f Hz of simulated time', rate)
        self.assertAlmostEqual(rate, 20.0, delta=1.5)

    def test_bad_entries_get_one_warning_each(self):
        for name, words in (('arm_controller', "joint 'arm_joint_01' is not a joint"),
                            ('gripper_controller', 'is not simulated here')):
            self.assertTrue(wait_until(lambda: self.rosout.lines(words, Log.WARN), 5.0), name)
            self.assertEqual(len(self.rosout.lines('controller %s:' % name, Log.WARN)), 1)

    def test_the_controller_manager_lists_them(self):
        rospy.wait_for_service('/robot/controller_manager/list_controllers', 10.0)
        listed = rospy.ServiceProxy('/robot/controller_manager/list_controllers',
                                    ListControllers)().controller
        running = {c.name: c.type for c in listed if c.state == 'running'}
        self.assertEqual(running['joint_head_controller'],
                         'effort_controllers/JointPositionController')
        self.assertIn('joint_position_controller', running)
        self.assertNotIn('arm_controller', running)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_controllers', TestControllers)

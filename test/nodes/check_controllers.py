#!/usr/bin/env python3
"""A user's controller YAML loaded under /robot after the simulator started:
its renamed controller moves the head, its joint-state rate is used, bad
entries get one warning each, and the default controller keeps working."""
import unittest

import rosparam
import rospy
import rostest
from controller_manager_msgs.srv import ListControllers
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64

from checks import Rosout, Watch, clock, eventually, wait_for_subscribers

USER_YAML = {
    'joint_state_controller': {'type': 'joint_state_controller/JointStateController',
                               'publish_rate': 20},
    'joint_head_controller': {'type': 'effort_controllers/JointPositionController',
                              'joint': 'head_joint', 'pid': {'p': 100.0, 'i': 0.1, 'd': 1.0}},
    'arm_controller': {'type': 'position_controllers/JointPositionController',
                       'joint': 'arm_joint_01'},
    'gripper_controller': {'type': 'effort_controllers/GripperActionController',
                           'joint': 'head_joint'},
    'tail_controller': {'type': 'position_controllers/JointPositionController'},
}


class TestControllers(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_controllers')
        clock()
        cls.rosout = Rosout()
        cls.rosout.connected('/gazebo')   # its warnings must reach us
        cls.joints = Watch('/robot/joint_states', JointState, keep=True)
        cls.joints.connected('/gazebo')      # the first messages come at once (rtf 0)
        cls.joints.next(30.0)
        rosparam.upload_params('/robot', USER_YAML)     # what rosparam load does: leaf by leaf

    def head(self):
        msg = self.joints.msg
        return msg.position[msg.name.index('head_joint')]

    def command(self, controller, value):
        pub = rospy.Publisher('/robot/%s/command' % controller, Float64, queue_size=1,
                              latch=True)
        wait_for_subscribers(pub)
        pub.publish(Float64(value))
        self.assertTrue(eventually(lambda: abs(self.head() - value) < 0.03),
                        '%s: head at %.3f, not %.3f' % (controller, self.head(), value))

    def test_the_renamed_controller_and_the_default_one_move_the_head(self):
        self.command('joint_head_controller', 0.7)
        self.command('joint_position_controller', -0.4)

    def test_the_yaml_s_joint_state_rate_is_used(self):
        def at_20_hz():           # the last few messages 0.05 s apart
            stamps = [m.header.stamp.to_sec() for m in self.joints.all[-5:]]
            return len(stamps) == 5 and all(abs(b - a - 0.05) < 1e-3
                                            for a, b in zip(stamps, stamps[1:]))
        self.assertTrue(eventually(at_20_hz))
        start = len(self.joints.all)
        clock().sleep(4.0)
        # published per simulated second (sequence numbers: one dropped on
        # its way on a loaded machine is not a lower rate)
        first, last = self.joints.all[start].header, self.joints.all[-1].header
        rate = (last.seq - first.seq) / (last.stamp.to_sec() - first.stamp.to_sec())
        rospy.loginfo('joint states at %.1f Hz of simulated time', rate)
        self.assertAlmostEqual(rate, 20.0, delta=1.5)

    def test_bad_entries_get_one_warning_each(self):
        # (a controller with no joint is warned about once the YAML has had
        # time to arrive, leaf by leaf: not while it is half-loaded)
        for name, words in (('arm_controller', "joint 'arm_joint_01' is not a joint"),
                            ('gripper_controller', 'is not simulated here'),
                            ('tail_controller', '/robot/tail_controller/joint is not set')):
            self.assertTrue(eventually(lambda: self.rosout.lines(words, Log.WARN)), name)
            self.assertEqual(len(self.rosout.lines('controller %s:' % name, Log.WARN)), 1)

    def test_the_controller_manager_lists_them(self):
        rospy.wait_for_service('/robot/controller_manager/list_controllers', 10.0)
        lister = rospy.ServiceProxy('/robot/controller_manager/list_controllers',
                                    ListControllers)

        def running():
            return {c.name: c.type for c in lister().controller if c.state == 'running'}
        self.assertTrue(eventually(lambda: 'joint_head_controller' in running()))
        running = running()
        self.assertEqual(running['joint_head_controller'],
                         'effort_controllers/JointPositionController')
        self.assertIn('joint_position_controller', running)
        self.assertNotIn('arm_controller', running)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_controllers', TestControllers)

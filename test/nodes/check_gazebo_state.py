#!/usr/bin/env python3
"""Gazebo's state topics and services on the running simulator: what course
code reads and writes through gazebo_msgs, and what it gets for bad input."""
import math
import time
import unittest

import rospy
import rostest
from gazebo_msgs.msg import LinkStates, ModelState, ModelStates
from gazebo_msgs.srv import (GetLinkState, GetModelState, GetWorldProperties, SetLinkState,
                             SetModelState)
from gazebo_msgs.msg import LinkState
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from std_srvs.srv import Empty

from checks import Pose, Rosout, Watch, clock, wait_until
from system_checks import wall_until, world_held

SERVICES = {'get_model_state': GetModelState, 'set_model_state': SetModelState,
            'get_link_state': GetLinkState, 'set_link_state': SetLinkState,
            'get_world_properties': GetWorldProperties, 'reset_simulation': Empty}


class TestGazeboState(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_gazebo_state')
        clock()
        cls.srv = {}
        for name, kind in SERVICES.items():
            rospy.wait_for_service('/gazebo/' + name, 30.0)
            cls.srv[name] = rospy.ServiceProxy('/gazebo/' + name, kind)
        cls.rosout = Rosout()
        cls.rosout.connected('/gazebo')   # its refusals must reach us
        cls.ball = Pose('/ball/odom')
        cls.ball.next(20.0)

    def test_1_model_states_and_link_states_name_every_model_and_link(self):
        models = Watch('/gazebo/model_states', ModelStates).next(10.0)
        self.assertEqual(set(models.name), {'arena', 'human', 'kennel', 'robot', 'ball'})
        robot = models.pose[models.name.index('robot')].position
        self.assertAlmostEqual(robot.x, -5.0, delta=0.05)
        links = Watch('/gazebo/link_states', LinkStates).next(10.0)
        self.assertIn('robot::camera_link', links.name)
        self.assertIn('ball::ball_link', links.name)
        props = self.srv['get_world_properties']()
        self.assertTrue(props.success)
        self.assertIn('kennel', props.model_names)

    def test_2_get_model_state_in_the_world_and_relative_to_a_model(self):
        robot = self.srv['get_model_state']('robot', '')
        self.assertTrue(robot.success)
        self.assertAlmostEqual(robot.pose.position.y, 7.0, delta=0.05)
        ball_from_robot = self.srv['get_model_state']('ball', 'robot')
        # the ball at (-7, 6) is 2 m ahead of the robot at (-5, 7) facing -x, 1 m to its left
        self.assertAlmostEqual(ball_from_robot.pose.position.x, 2.0, delta=0.1)
        self.assertAlmostEqual(ball_from_robot.pose.position.y, 1.0, delta=0.1)
        link = self.srv['get_link_state']('ball::ball_link', '')
        self.assertTrue(link.success)
        self.assertAlmostEqual(link.link_state.pose.position.x, -7.0, delta=0.05)

    def test_3_set_model_state_moves_the_ball(self):
        state = ModelState(model_name='ball')
        state.pose.position.x, state.pose.position.y, state.pose.position.z = 1.0, 2.0, 0.5
        answer = self.srv['set_model_state'](state)
        self.assertTrue(answer.success, answer.status_message)
        self.assertTrue(wait_until(lambda: abs(self.ball.msg.pose.pose.position.x - 1.0) < 1e-3
                                   and abs(self.ball.msg.pose.pose.position.y - 2.0) < 1e-3, 5.0))

    def test_4_bad_states_are_refused_with_one_line(self):
        # services only: the world stands still, and the waits are for wall-time
        # throttles
        with world_held():
            time.sleep(1.1)   # a refusal of the tests before is out of the throttle's second
            state = ModelState(model_name='ball')
            state.pose.position.x = float('nan')
            start = time.monotonic()
            answer = self.srv['set_model_state'](state)
            self.assertFalse(answer.success)
            self.assertIn('not finite', answer.status_message)
            answer = self.srv['set_model_state'](ModelState(model_name='unicorn'))
            both = time.monotonic() - start
            self.assertFalse(answer.success)
            self.assertIn("no model named 'unicorn'", answer.status_message)
            head = LinkState(link_name='robot::head_link')
            head.pose.orientation.w = 1.0
            answer = self.srv['set_link_state'](head)
            self.assertFalse(answer.success)
            self.assertIn('only the root link', answer.status_message)
            answer = self.srv['get_link_state']('robot::elbow', '')
            self.assertFalse(answer.success)
            self.assertIn("no link 'elbow'", answer.status_message)
            # one line per service and second (of wall time: throttling is about the
            # log's volume): a second refusal within the second is counted a second
            # later; on a loaded machine the two calls took more than a second, and
            # the second had its own line
            held = '/gazebo/set_model_state: 1 more refused'
            alone = "/gazebo/set_model_state: refused: no model named 'unicorn'"
            self.assertTrue(wall_until(lambda: self.rosout.lines(held, Log.ERROR)
                                       or self.rosout.lines(alone, Log.ERROR)),
                            'the second refusal was neither counted nor logged')
            if both < 1.0:
                self.assertTrue(self.rosout.lines(held, Log.ERROR),
                                'no count of the refusal held back (both came in %.2f s)' % both)
            # each on its way to us: a reply can overtake the line logged before it
            for words in ('/gazebo/set_model_state: refused: the pose', 'only the root link',
                          "/gazebo/get_link_state: refused: model robot has no link 'elbow'"):
                self.assertTrue(wall_until(lambda: self.rosout.lines(words, Log.ERROR)), words)
                self.assertEqual(len(self.rosout.lines(words, Log.ERROR)), 1, words)

    def test_4b_no_body_can_be_put_off_the_world(self):
        before = self.srv['get_model_state']('robot', '').pose.position
        for x in (100.0, 1.0e300):                  # beyond the walls; where physics breaks
            state = ModelState(model_name='robot')
            state.pose.position.x, state.pose.position.z = x, 0.1
            answer = self.srv['set_model_state'](state)
            self.assertFalse(answer.success, x)
            self.assertIn('is outside the world (x in [-9.8, 9.8], y in [-9.8, 9.8]',
                          answer.status_message)
        link = LinkState(link_name='ball::ball_link')
        link.pose.position.y = -1.0e6
        answer = self.srv['set_link_state'](link)
        self.assertFalse(answer.success)
        self.assertIn('outside the world', answer.status_message)
        state = ModelState(model_name='ball')
        state.pose.position.z = 0.5
        state.twist.linear.x = 1.0e4
        answer = self.srv['set_model_state'](state)
        self.assertFalse(answer.success)
        self.assertIn('faster than 1000 m/s or rad/s', answer.status_message)
        after = self.srv['get_model_state']('robot', '').pose.position
        self.assertLess(math.hypot(after.x - before.x, after.y - before.y), 0.5)
        self.assertGreater(after.z, 0.0)

    def test_5_reset_simulation_sets_time_and_world_back(self):
        clock().sleep(1.0)
        self.assertGreater(rospy.get_time(), 2.0)
        odom = Watch('/ball/odom', Odometry, keep=True)
        odom.next(5.0)
        self.srv['reset_simulation']()

        def back_at_zero():       # a message of the reset world, stamped near 0
            return [m for m in odom.all if m.header.stamp.to_sec() < 1.0
                    and abs(m.pose.pose.position.x + 7.0) < 1e-3]
        self.assertTrue(wait_until(back_at_zero, 5.0),
                        [m.header.stamp.to_sec() for m in odom.all[-3:]])
        robot = self.srv['get_model_state']('robot', '')
        self.assertLess(math.hypot(robot.pose.position.x + 5.0, robot.pose.position.y - 7.0),
                        0.05)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_gazebo_state', TestGazeboState)

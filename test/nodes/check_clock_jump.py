#!/usr/bin/env python3
"""A second /clock publisher for 2 s (this checker: stamps 0, 2^31-1 and
2^32-1 s between the simulator's): the simulator names it in an ERROR line;
no node of the package dies; the dog, looking for its hidden ball, drives
again within 10 s of wall time once the stamps stop, and both action servers
still finish goals."""
import math
import time
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import Twist
from rosgraph_msgs.msg import Clock, Log

from checks import DogObserver, Watch, clock, node_pid, wait_until
from exp_assignment2.msg import PlanningAction
from exp_assignment2.planning import make_goal

STAMPS = (rospy.Time(0, 1), rospy.Time(2 ** 31 - 1), rospy.Time(2 ** 32 - 1))
NODES = ('/gazebo', '/state_machine', '/go_to_point_robot', '/go_to_point_ball',
         '/move_ball_around', '/human_commands')


class TestClockJump(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_clock_jump')
        clock()
        cls.dog = DogObserver()
        cls.rosout = cls.dog.rosout
        cls.cmd = Watch('/robot/cmd_vel', Twist, keep=True)
        cls.ball = actionlib.SimpleActionClient('/reaching_goal', PlanningAction)
        assert cls.ball.wait_for_server(rospy.Duration(60))
        cls.stray = rospy.Publisher('/clock', Clock, queue_size=10)

    def moves(self, since):
        """Velocity commands received after wall time ``since`` that move the robot."""
        with self.cmd.lock:
            return [m for t, m in zip(self.cmd_times, self.cmd.all[self.cmd_before:])
                    if t > since and (abs(m.linear.x) > 0.01 or abs(m.angular.z) > 0.01)]

    def test_a_second_clock_is_named_and_the_dog_drives_again(self):
        self.assertTrue(wait_until(lambda: self.dog.state() == 'NORMAL', 30.0))
        self.assertTrue(wait_until(lambda: self.dog.robot.msg is not None, 10.0))
        pids = {name: node_pid(name) for name in NODES}
        self.assertNotIn(None, pids.values(), pids)
        self.cmd_before, self.cmd_times = len(self.cmd.all), []
        self.cmd.on_message = lambda msg: self.cmd_times.append(time.monotonic())
        end, sent = time.monotonic() + 2.0, 0
        while time.monotonic() < end:
            self.stray.publish(Clock(clock=STAMPS[sent % 3]))
            sent += 1
            time.sleep(0.01)
        stopped = time.monotonic()
        rospy.loginfo('sent %d stray /clock stamps in 2 s', sent)
        x0, y0, _, yaw0 = self.dog.robot.xyzyaw()

        def driven():
            x, y, _, yaw = self.dog.robot.xyzyaw()
            turned = abs(math.atan2(math.sin(yaw - yaw0), math.cos(yaw - yaw0)))
            return math.hypot(x - x0, y - y0) > 0.2 or turned > 0.3
        while time.monotonic() < stopped + 10.0 and not (self.moves(stopped) and driven()):
            time.sleep(0.1)
        rospy.loginfo('after the stray clock: %d moving commands, robot moved: %s, '
                      '%.1f s of wall time', len(self.moves(stopped)), driven(),
                      time.monotonic() - stopped)
        self.assertTrue(self.moves(stopped), 'no /robot/cmd_vel that moves within 10 s')
        self.assertTrue(driven(), 'the robot did not move within 10 s')

        named = self.rosout.lines('%s publishes it too' % rospy.get_name(), Log.ERROR, '/gazebo')
        self.assertTrue(named, 'no ERROR line of the simulator names the second publisher')
        self.assertEqual({name: node_pid(name) for name in NODES}, pids, 'a node restarted')

        self.ball.send_goal(make_goal(3.0, -2.0, -1.0))        # stays hidden
        self.assertTrue(self.ball.wait_for_result(rospy.Duration(60)))
        self.assertEqual(self.ball.get_state(), GoalStatus.SUCCEEDED)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_clock_jump', TestClockJump)

#!/usr/bin/env python3
"""Does the original assignment's follower
(test/original/robot_to_ball_original.py, seed 000's robot_to_ball.py:
angular.z = 0.002*(cx-400), linear.x = -0.01*(radius-100)), run unmodified
against robot_model:=original, bring the robot to rest near the ball, facing
it?

Twice: from the spawn pose (ball 2.2 m away, 27 deg to the left: the robot
must turn left and back off), then after the ball is moved 4.7 m away through
/reaching_goal (the robot must turn and drive forward). "At rest" means the
follower's commands stay below 0.01 m/s and 0.01 rad/s for 2 s of ROS time
(commands that stop coming are not rest). The control law rests where the ball
looks 100 px in radius in the 800 px image: about 2.7 m from the chassis with
the 80 deg camera.

With a robot that turns the other way (robot_model:=rep103) the follower turns
away from the ball and never comes to rest facing it: this fails.
"""
import math
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import Twist

from checks import Pose, SimpleClient, Watch, clock, finished, wait_until
from exp_assignment2.msg import PlanningAction
from exp_assignment2.planning import make_goal

REST_TWIST = (0.01, 0.01)    # m/s, rad/s: below both is "not moving"
REST_FOR = 2.0               # s of ROS time without moving: "at rest"
NEAR = (2.0, 3.5)            # m, chassis to ball centre (the law rests at ~2.7 m)
FACING = math.radians(3.0)   # the ball within 3 deg of the robot's heading
BALL_GOAL = (-8.0, 4.0)      # 4.7 m from where the robot first rests, in view


class FollowerCommands(Watch):
    """/robot/cmd_vel: the ROS time of the first command, of the last one, and
    of the last one that moved (above REST_TWIST)."""

    def __init__(self):
        self.first = self.last = None
        self.last_moving = 0.0
        Watch.__init__(self, '/robot/cmd_vel', Twist)

    def on_message(self, msg):
        now = rospy.get_time()
        if self.first is None:
            self.first = now
        self.last = now
        if abs(msg.linear.x) > REST_TWIST[0] or abs(msg.angular.z) > REST_TWIST[1]:
            self.last_moving = now

    def rest_start(self, since):
        return max(self.last_moving, since)

    def rested(self, since):
        """The follower has commanded rest for REST_FOR s, counting from
        ``since`` at the earliest: commands that stop coming are not rest (a
        loaded machine can hold the follower's process for a wall second)."""
        return self.last is not None and self.last - self.rest_start(since) >= REST_FOR


class TestOriginalFollower(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_original_follower')
        clock()
        cls.robot, cls.ball = Pose('/robot/odom'), Pose('/ball/odom')
        cls.cmd = FollowerCommands()
        cls.ball_server = SimpleClient('/reaching_goal', PlanningAction)

    def geometry(self):
        """(distance, bearing) of the ball from the robot."""
        rx, ry, _, ryaw = self.robot.xyzyaw()
        bx, by, _, _ = self.ball.xyzyaw()
        bearing = math.atan2(by - ry, bx - rx) - ryaw
        return math.hypot(bx - rx, by - ry), math.atan2(math.sin(bearing), math.cos(bearing))

    def geometry_deg(self):
        if self.robot.msg is None or self.ball.msg is None:
            return float('nan'), float('nan')
        distance, bearing = self.geometry()
        return distance, math.degrees(bearing)

    def rest_near_ball(self, since, start, what):
        """At rest (counting from ``since``), facing the ball, near it; the
        time to rest is counted from ``start``."""
        self.assertTrue(wait_until(lambda: self.cmd.rested(since), 60.0),
                        '%s: the robot is not at rest 60 s later (distance %.2f m, '
                        'bearing %.1f deg)' % ((what,) + self.geometry_deg()))
        rest = self.cmd.rest_start(since) - start
        distance, bearing = self.geometry_deg()
        print('[check_original_follower] %s: at rest %.1f s (ROS time) later, %.3f m from '
              'the ball, bearing %.2f deg' % (what, rest, distance, bearing))
        self.assertLess(abs(bearing), math.degrees(FACING),
                        '%s: at rest but not facing the ball (bearing %.1f deg)' % (what, bearing))
        self.assertTrue(NEAR[0] < distance < NEAR[1],
                        '%s: at rest %.2f m from the ball' % (what, distance))

    def test_follower_brings_the_robot_to_rest_near_the_ball(self):
        self.assertTrue(wait_until(lambda: self.cmd.first is not None, 120.0),
                        'the follower never published on /robot/cmd_vel')
        self.assertTrue(wait_until(lambda: self.ball.msg is not None, 10.0), 'no /ball/odom')
        self.rest_near_ball(self.cmd.first, self.cmd.first, 'from the first command')

        self.assertTrue(self.ball_server.wait_for_server(rospy.Duration(30)))
        moved = rospy.get_time()
        self.ball_server.send_goal(make_goal(BALL_GOAL[0], BALL_GOAL[1], 0.5))
        self.assertTrue(finished(self.ball_server, 30.0))
        self.assertEqual(self.ball_server.get_state(), GoalStatus.SUCCEEDED)
        arrived = rospy.get_time()
        print('[check_original_follower] the ball reached %s %.1f s after the goal'
              % (BALL_GOAL, arrived - moved))
        self.rest_near_ball(arrived, moved, 'from the ball goal %s' % (BALL_GOAL,))


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_original_follower', TestOriginalFollower)

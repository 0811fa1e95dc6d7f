#!/usr/bin/env python3
"""robot_to_ball.py alone: the dog comes to the ball, and follows it when
the ball is moved away."""
import rostest

from checks import DogCheck, wait_until


class TestRobotToBall(DogCheck):
    NODE = 'check_robot_to_ball'

    def test_follows_the_ball(self):
        self.assertTrue(wait_until(lambda: self.dog.ball_distance() < 1.5, 60.0),
                        'distance %.2f m' % self.dog.ball_distance())
        self.tell_the_ball('go to -2 4')
        # human_commands, then the ball's server: a few hops at many times real time
        self.assertTrue(wait_until(lambda: self.dog.ball_distance() > 2.0, 15.0))
        self.assertTrue(wait_until(lambda: self.dog.ball_distance() < 1.5, 60.0),
                        'distance %.2f m' % self.dog.ball_distance())


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_robot_to_ball', TestRobotToBall)

#!/usr/bin/env python3
"""Scenario A: while the dog wanders to a random goal, the ball appears
ahead of it (put there through Gazebo's /gazebo/set_model_state, so it is
there at once whatever the robot's speed); the robot goal is preempted and
the dog plays."""
import math

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import SetModelState

from checks import DogCheck, Watch, clock, wait_until
from exp_assignment2.msg import PlanningActionGoal, PlanningActionResult


class TestDogPreempt(DogCheck):
    NODE = 'check_dog_preempt'

    @classmethod
    def setUpClass(cls):
        super(TestDogPreempt, cls).setUpClass()
        cls.goals = Watch('/robot_reaching_goal/goal', PlanningActionGoal)
        cls.results = Watch('/robot_reaching_goal/result', PlanningActionResult, keep=True)

    def test_ball_seen_preempts_the_robot_goal(self):
        self.assertTrue(wait_until(lambda: self.goals.msg is not None, 90.0),
                        'the dog never wandered')
        self.assertNotIn('PLAY', [s for _, s in self.dog.states])
        # the ball on the way to the goal, which the robot is turning to face
        # (ahead of its heading of the moment it may turn away: seen in 1 of 10 runs)
        clock().sleep(1.0)
        x, y, _, _ = self.dog.robot.xyzyaw()
        target = self.goals.msg.goal.target_pose.pose.position
        gap = math.hypot(target.x - x, target.y - y)
        share = min(1.0, 3.0 / gap) if gap > 0 else 0.0
        ahead = (max(-7.5, min(7.5, x + share * (target.x - x))),
                 max(-7.5, min(7.5, y + share * (target.y - y))))
        state = ModelState(model_name='ball')
        state.pose.position.x, state.pose.position.y, state.pose.position.z = ahead + (0.5,)
        rospy.wait_for_service('/gazebo/set_model_state', 10.0)
        answer = rospy.ServiceProxy('/gazebo/set_model_state', SetModelState)(state)
        self.assertTrue(answer.success, answer.status_message)
        self.assertTrue(wait_until(lambda: self.dog.entered('PLAY'), 60.0),
                        'states: %s' % self.dog.states)
        active = self.goals.msg.goal_id.id          # PLAY sends none: the wander it ended

        def preempted():
            return [r for r in self.results.all if r.status.goal_id.id == active
                    and r.status.status == GoalStatus.PREEMPTED]
        self.assertTrue(wait_until(preempted, 10.0), 'results: %s' % [
            (r.status.goal_id.id, r.status.status) for r in self.results.all])


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_dog_preempt', TestDogPreempt)

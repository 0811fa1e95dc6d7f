#!/usr/bin/env python3
"""Scenario A: while the dog wanders to a random goal, the ball appears ahead;
the robot goal is preempted and the dog plays."""
import math
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from std_msgs.msg import String

from dog_checks import DogObserver, Watch, wait_until
from exp_assignment2.msg import PlanningActionGoal, PlanningActionResult
from exp_assignment2.simulator import yaw_of


class TestDogPreempt(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_dog_preempt')
        cls.dog = DogObserver()
        cls.goals = Watch('/robot_reaching_goal/goal', PlanningActionGoal)
        cls.results = []
        rospy.Subscriber('/robot_reaching_goal/result', PlanningActionResult,
                         cls.results.append, queue_size=10)
        cls.command = rospy.Publisher('/ball/command', String, queue_size=10)

    def test_ball_seen_preempts_the_robot_goal(self):
        self.assertTrue(wait_until(lambda: self.goals.msg is not None, 60.0),
                        'the dog never wandered')
        self.assertNotIn('PLAY', [s for _, s in self.dog.states])
        rospy.sleep(1.0)
        pose = self.dog.robot.msg.pose.pose
        yaw = yaw_of((pose.orientation.x, pose.orientation.y, pose.orientation.z,
                      pose.orientation.w))
        x = max(-7.5, min(7.5, pose.position.x + 3.0 * math.cos(yaw)))
        y = max(-7.5, min(7.5, pose.position.y + 3.0 * math.sin(yaw)))
        active_goal = self.goals.msg.goal_id.id
        while self.command.get_num_connections() == 0:
            rospy.sleep(0.1)
        self.command.publish(String('go to %.2f %.2f' % (x, y)))
        self.assertTrue(wait_until(lambda: self.dog.state() == 'PLAY', 40.0),
                        'states: %s' % [s for _, s in self.dog.states])
        def preempted():
            return [r for r in self.results if r.status.status == GoalStatus.PREEMPTED]
        self.assertTrue(wait_until(preempted, 5.0), 'results: %s' % [(r.status.goal_id.id, r.status.status)
                                                    for r in self.results])
        rospy.loginfo('goal %s active when the ball came; preempted: %s', active_goal,
                      [r.status.goal_id.id for r in preempted()])


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_dog_preempt', TestDogPreempt)

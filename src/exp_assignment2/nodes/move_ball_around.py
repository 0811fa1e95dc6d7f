"""``move_ball_around``: the ball's own routine (random goals, waits,
disappearances), paused while ``/ball/auto`` (std_msgs/Bool, latched by
``human_commands``) is false.

Parameters: ``~seed``, ``~wait_time``, ``~hidden_time``, ``~moves_per_round``,
``~goal_timeout``, ``~start_enabled``.
"""
import random

import rospy
from std_msgs.msg import Bool

from exp_assignment2.behaviour.ball import BallRoutine
from exp_assignment2.ros.actions import start_client
from exp_assignment2.ros.log import RosLog

AUTO_TOPIC = '/ball/auto'


def main():
    clock, ball = start_client('move_ball_around', '/reaching_goal')
    if ball is None:
        return
    routine = BallRoutine(
        clock, ball, random.Random(rospy.get_param('~seed', 1)), RosLog(),
        wait_time=float(rospy.get_param('~wait_time', 8.0)),
        hidden_time=float(rospy.get_param('~hidden_time', 10.0)),
        moves_per_round=int(rospy.get_param('~moves_per_round', 2)),
        goal_timeout=float(rospy.get_param('~goal_timeout', 60.0)),
        enabled=bool(rospy.get_param('~start_enabled', True)))
    rospy.Subscriber(AUTO_TOPIC, Bool, lambda msg: routine.set_enabled(msg.data), queue_size=10)
    routine.run()

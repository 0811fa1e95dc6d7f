"""``state_machine``: the dog's behaviour (NORMAL, SLEEP, PLAY) on ROS.

Parameters: ``~seed`` and every number of
:class:`~exp_assignment2.behaviour.dog.DogParams` (``config/dog.yaml``),
``~min_radius_at_800``, ``~gui``. Publishes the active state on
``/robot/state`` (latched) and in the ``/state`` parameter.
"""
import random

import rospy
from std_msgs.msg import String

from exp_assignment2.behaviour.dog import Dog, DogParams, build_state_machine
from exp_assignment2.ros.actions import PlanningClient
from exp_assignment2.ros.clock import RosClock
from exp_assignment2.ros.dog import RosDogBody, RosDogEyes
from exp_assignment2.ros.ending import run_until_shutdown
from exp_assignment2.ros.log import RosLog
from exp_assignment2.ros.robot_model import robot_name, turn_sign
from exp_assignment2.smach_api import log_to, report_active_state


def main():
    rospy.init_node('state_machine')
    try:
        params = DogParams(lambda key, default: rospy.get_param('~' + key, default))
    except ValueError as exc:
        rospy.logfatal('state_machine: %s', exc)
        raise SystemExit(1)
    clock = RosClock()
    # the camera's first subscriber starts the world (simulator wait_for_camera):
    # the eyes before any wait for time
    eyes = RosDogEyes(clock, float(rospy.get_param('~min_radius_at_800', 10.0)),
                      gui=bool(rospy.get_param('~gui', False)))
    robot = PlanningClient('/robot_reaching_goal', clock)
    if not robot.wait_for_server():
        return
    body = RosDogBody(turn_sign(), robot)
    dog = Dog(clock, body, eyes, params, random.Random(rospy.get_param('~seed', 0)), RosLog())
    # every state reaches every subscriber: NORMAL then SLEEP 0.01 s later are two messages
    state_pub = rospy.Publisher(robot_name('state'), String, queue_size=10, latch=True)

    def report(label):
        rospy.loginfo('state: %s', label)
        rospy.set_param('/state', label)
        state_pub.publish(String(label))
    sm = build_state_machine(dog)
    # the state is reported on its topic: SMACH's own lines only at debug level
    log_to(rospy.logdebug, rospy.logwarn, rospy.logdebug, rospy.logerr)
    report_active_state(sm, report)
    run_until_shutdown(sm.execute)

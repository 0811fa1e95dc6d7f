"""``state_manager``: MiRo's behaviour (SLEEP, NORMAL, PLAY) on ROS.

Parameters: ``~seed``, ``~simulate_person``, ``~person_x``, ``~person_y`` and
the numbers of :class:`~exp_assignment2.behaviour.miro.MiroParams`. Publishes
the state on ``/state`` (latched) and in the original's ``/state`` parameter.
"""
import random

import rospy
from gazebo_msgs.msg import ModelState
from std_msgs.msg import String

from exp_assignment2 import grid
from exp_assignment2.behaviour.miro import STATE_PARAM, Miro, MiroParams, build_state_machine
from exp_assignment2.behaviour.person import Ears, Person, SimulatedPerson
from exp_assignment2.ros.clock import RosClock
from exp_assignment2.ros.ending import run_until_shutdown
from exp_assignment2.ros.log import RosLog, refusal_log
from exp_assignment2.ros.miro import RosMiroBody, listen
from exp_assignment2.smach_api import log_to, report_active_state


def person_model_mover():
    """Moves the world's ``person`` model (rviz shows it, see world_miro.yaml)
    where a gesture puts the person, through Gazebo's set_model_state topic."""
    pub = rospy.Publisher('/gazebo/set_model_state', ModelState, queue_size=10)

    def move(place):
        state = ModelState(model_name='person')
        state.pose.position.x, state.pose.position.y = place
        state.pose.orientation.z, state.pose.orientation.w = 1.0, 0.0   # facing -x
        pub.publish(state)
    return move


def main():
    rospy.init_node('state_manager')
    try:
        params = MiroParams(lambda key, default: rospy.get_param('~' + key, default))
        where = (int(rospy.get_param('~person_x', grid.PERSON[0])),
                 int(rospy.get_param('~person_y', grid.PERSON[1])))
        if not grid.on_grid(*where):
            raise ValueError('~person_x, ~person_y %s is off the grid' % (where,))
    except ValueError as exc:
        rospy.logfatal('state_manager: %s', exc)
        raise SystemExit(1)
    seed = rospy.get_param('~seed', 0)
    clock, log = RosClock(), RosLog()
    simulated = (SimulatedPerson(random.Random(seed))
                 if rospy.get_param('~simulate_person', True) else None)
    if not clock.wait_for_time():           # a respawned node's lines carry ROS time
        return
    ears = Ears(clock, log, params.voice_timeout)
    person = Person(where, simulated, on_move=person_model_mover())
    listen(ears, person, refusal_log)
    miro = Miro(clock, RosMiroBody(clock), ears, person, params, random.Random(seed), log,
                simulated=simulated)
    state_pub = rospy.Publisher('/state', String, queue_size=10, latch=True)

    def report(label):
        rospy.set_param('/state', STATE_PARAM[label])
        state_pub.publish(String(STATE_PARAM[label]))
    sm = build_state_machine(miro)
    # the state is reported on its topic: SMACH's own lines only at debug level
    log_to(rospy.logdebug, rospy.logwarn, rospy.logdebug, rospy.logerr)
    report_active_state(sm, report)
    run_until_shutdown(sm.execute)

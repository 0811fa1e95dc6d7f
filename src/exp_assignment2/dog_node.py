"""Entry points of scenario A's dog: ``state_machine.py`` and ``robot_to_ball.py``."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String

from exp_assignment2.dog_io import BallFollower, BallWatcher
from exp_assignment2.dog_states import Dog, DogParams, build_state_machine
from exp_assignment2.smach_api import report_active_state


class StateReporter(object):
    """Publishes the active state on ``/robot/state`` (latched) and sets ``/state``."""

    def __init__(self):
        self.pub = rospy.Publisher('/robot/state', String, queue_size=1, latch=True)

    def __call__(self, label):
        rospy.loginfo('state: %s', label)
        rospy.set_param('/state', label)
        self.pub.publish(String(label))


def main_state_machine():
    rospy.init_node('state_machine')
    watcher = BallWatcher(gui=rospy.get_param('~gui', False))
    try:
        dog = Dog(watcher, DogParams(), seed=rospy.get_param('~seed', 0))
    except RuntimeError as exc:
        rospy.logfatal('state_machine: %s', exc)
        raise SystemExit(1)
    sm = build_state_machine(dog)
    report_active_state(sm, StateReporter())
    try:
        sm.execute()
    except Exception:
        if not rospy.is_shutdown():    # a sleep interrupted by Ctrl-C is no error
            raise


def main_robot_to_ball():
    """The original stand-alone follower: chase the ball, turn when it is not seen."""
    rospy.init_node('robot_to_ball')
    watcher = BallWatcher(gui=rospy.get_param('~gui', False))
    watcher.attach(BallFollower(rospy.Publisher('/robot/cmd_vel', Twist, queue_size=1)))
    rospy.spin()

"""Scenario B's nodes: state manager, geometry grounding, motion controller,
info printer. Each ``main_*`` is the body of a script in ``scripts/``."""
import math
import random

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64MultiArray, Int64MultiArray, String

from exp_assignment2.commands import CommandError
from exp_assignment2.control import planar_velocity
from exp_assignment2.grounding import ground
from exp_assignment2.miro_person import Person
from exp_assignment2.miro_states import STATE_PARAM, Miro, MiroParams, build_state_machine
from exp_assignment2.smach_api import report_active_state
from exp_assignment2.world import MIRO_HOME, on_grid


def main_state_manager():
    rospy.init_node('state_manager')
    seed = rospy.get_param('~seed', 0)
    person = Person(simulate=rospy.get_param('~simulate_person', True), seed=seed)
    miro = Miro(person, MiroParams(), seed=seed)
    state_pub = rospy.Publisher('/state', String, queue_size=10, latch=True)

    def report(label):
        rospy.set_param('/state', STATE_PARAM[label])
        state_pub.publish(String(STATE_PARAM[label]))
    sm = build_state_machine(miro)
    report_active_state(sm, report)
    try:
        sm.execute()
    except Exception:
        if not rospy.is_shutdown():
            raise


def main_geometry_grounding():
    rospy.init_node('geometry_grounding')
    rng = random.Random(rospy.get_param('~seed', 0))
    pub = rospy.Publisher('/target_pos', Int64MultiArray, queue_size=10)

    def on_command(msg):
        home = (rospy.get_param('/home_posx', MIRO_HOME[0]), rospy.get_param('/home_posy', MIRO_HOME[1]))
        try:
            x, y = ground(msg.data, home, rng)
        except CommandError as exc:
            rospy.logerr('/command: %s', exc)
            return
        pub.publish(Int64MultiArray(data=[x, y]))
    rospy.Subscriber('/command', String, on_command, queue_size=10)
    rospy.spin()


class OmniMotionController(object):
    """Drives the omnidirectional robot to ``/target_pos`` at a fixed rate.

    On arrival: stops, publishes ``/arrival`` ([target_x, target_y, x, y,
    number]) and sets ``/arrived`` = 1 and ``/all`` for tools that read them.
    """

    def __init__(self):
        self.kp = float(rospy.get_param('~kp', 1.0))
        self.max_speed = float(rospy.get_param('~max_speed', 1.0))
        self.tolerance = float(rospy.get_param('~tolerance', 0.05))
        self.target, self.pose, self.number = None, None, 1
        self.cmd_pub = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
        self.arrival_pub = rospy.Publisher('/arrival', Float64MultiArray, queue_size=10)
        rospy.set_param('/arrived', 1)
        rospy.Subscriber('/odom', Odometry, self._on_odom, queue_size=1)
        rospy.Subscriber('/target_pos', Int64MultiArray, self._on_target, queue_size=10)
        rospy.Timer(rospy.Duration(1.0 / float(rospy.get_param('~rate', 20.0))), self._tick)

    def _on_odom(self, msg):
        self.pose = msg.pose.pose.position

    def _on_target(self, msg):
        if len(msg.data) != 2 or not on_grid(msg.data[0], msg.data[1]):
            rospy.logerr('/target_pos: %s is not a grid point [x, y] in [0, 10]; ignored',
                         list(msg.data))
            return
        self.target = (msg.data[0], msg.data[1])

    def _tick(self, _event):
        target, pose = self.target, self.pose
        if target is None or pose is None:
            return
        if math.hypot(target[0] - pose.x, target[1] - pose.y) <= self.tolerance:
            self.target = None
            self.cmd_pub.publish(Twist())
            report = [float(target[0]), float(target[1]), pose.x, pose.y, float(self.number)]
            rospy.set_param('/all', report)
            rospy.set_param('/arrived', 1)
            self.arrival_pub.publish(Float64MultiArray(data=report))
            self.number += 1
            return
        twist = Twist()
        twist.linear.x, twist.linear.y = planar_velocity(pose.x, pose.y, target[0], target[1],
                                                         self.kp, self.max_speed)
        self.cmd_pub.publish(twist)


def main_motion_controller():
    rospy.init_node('robot_motion_controller')
    OmniMotionController()
    rospy.spin()


def main_print_info():
    """Logs every state change, command, target and arrival as it happens."""
    rospy.init_node('print_info')
    rospy.Subscriber('/state', String, lambda m: rospy.loginfo('state: %s', m.data),
                     queue_size=100)
    rospy.Subscriber('/command', String, lambda m: rospy.loginfo('command: %s', m.data),
                     queue_size=100)
    rospy.Subscriber('/target_pos', Int64MultiArray,
                     lambda m: rospy.loginfo('target: (%d, %d)', *m.data[:2]), queue_size=100)
    rospy.Subscriber('/arrival', Float64MultiArray, lambda m: rospy.loginfo(
        'arrival #%d: target (%g, %g), robot at (%.2f, %.2f)', int(m.data[4]), *m.data[:4]),
        queue_size=100)
    rospy.spin()

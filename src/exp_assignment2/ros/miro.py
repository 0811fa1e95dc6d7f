"""MiRo over ROS (scenario B): the manager's body, the person's words and
gestures, and the omnidirectional motion controller.

The manager publishes ``/command``; ``geometry_grounding`` answers on
``/target_pos`` (Int64MultiArray ``[x, y]`` whose one dimension's label is
the command it grounds, so an answer is matched to its order); the motion
controller drives there and announces ``/arrival`` ([target_x, target_y, x,
y, number]). It alone writes the original's ``/arrived`` and ``/all``
parameters.
"""
import math
import threading
import time

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64MultiArray, Int64MultiArray, String

from exp_assignment2 import grid
from exp_assignment2.control import planar_velocity
from exp_assignment2.geometry import world_to_body, yaw_of
from exp_assignment2.grammar import parse_voice, quote
from exp_assignment2.msg import Gesture
from exp_assignment2.refusal import parse_or_refuse
from exp_assignment2.ros.log import refusal_log

ACK_TIMEOUT = 1.0   # s of ROS time, and of wall time, for the grounding node to answer
QUIET_TRIES = 10    # unanswered orders sent again before a warning


class MiroGoal(object):
    """One order: acknowledged by its ``/target_pos``, done at its ``/arrival``
    or when a later order replaces it. An order grounded twice (sent again
    before the first answer came) takes the later target: the controller
    drives to the newest one. An arrival that comes before the target (the
    two are on different topics; MiRo already there arrives at once) is kept
    and counts when its target comes."""

    def __init__(self, command):
        self.command, self.target, self.state = command, None, 'sent'
        self.early = set()      # targets arrived at while this order awaited its target
        self.grounded = threading.Event()      # its first target came

    def done(self):
        return self.state in ('arrived', 'abandoned')

    def succeeded(self):
        return self.state == 'arrived'

    def cancel(self):
        if not self.done():
            self.state = 'abandoned'


class RosMiroBody(object):
    """:class:`~exp_assignment2.behaviour.interfaces.MiroBody` over ROS."""

    def __init__(self, clock):
        self.clock, self.goal = clock, None
        self.lock = threading.Lock()
        self.pub = rospy.Publisher('/command', String, queue_size=10)
        rospy.Subscriber('/target_pos', Int64MultiArray, self._on_target, queue_size=10)
        rospy.Subscriber('/arrival', Float64MultiArray, self._on_arrival, queue_size=10)

    def go(self, command):
        """Publish ``command`` until grounded (an order sent before the
        grounding node listens would be lost); returns its :class:`MiroGoal`."""
        goal = MiroGoal(command)
        with self.lock:
            if self.goal is not None:
                self.goal.cancel()
            self.goal = goal
        tries = 0
        while not self.clock.is_shutdown():
            self.pub.publish(String(command))
            if self._answered(goal):
                break
            tries += 1
            if tries % QUIET_TRIES == 0:   # the first ones: the grounding node is starting
                rospy.logwarn('%r: no answer on /target_pos for %.0f s; sending again',
                              command, tries * ACK_TIMEOUT)
        return goal

    def _answered(self, goal):
        """Whether ``goal`` was grounded within ACK_TIMEOUT of ROS time and
        of wall time: at real_time_factor 0 a second of ROS time may be 50 ms
        of wall time, and an order sent again too soon is grounded twice (two
        random targets for one 'go_rand')."""
        sent = time.monotonic()
        if self.clock.wait_until(lambda: goal.target is not None, ACK_TIMEOUT):
            return True
        return goal.grounded.wait(max(0.0, ACK_TIMEOUT - (time.monotonic() - sent)))

    def _on_target(self, msg):
        label = msg.layout.dim[0].label if msg.layout.dim else None
        with self.lock:
            goal = self.goal
            if goal is None or goal.done() or label != goal.command:
                return
            goal.target = tuple(msg.data[:2])
            goal.state = 'arrived' if goal.target in goal.early else 'moving'
        goal.grounded.set()
        self.clock.notify()

    def _on_arrival(self, msg):
        target = tuple(msg.data[:2])
        with self.lock:
            goal = self.goal
            if goal is not None and goal.state == 'sent':
                goal.early.add(target)
            if goal is None or goal.state != 'moving' or target != goal.target:
                return
            goal.state = 'arrived'
        self.clock.notify()


def listen(ears, person, refuse):
    """Feed ``/voice`` to the ears and ``/gesture`` to the person; ``refuse(topic)``
    gives the refusal log of a topic."""
    voice_refusal, gesture_refusal = refuse('/voice'), refuse('/gesture')

    def on_voice(msg):
        cmd = parse_or_refuse(parse_voice, msg.data, voice_refusal)
        if cmd is not None:
            rospy.loginfo('/voice: the person says %s', quote(msg.data.strip()))
            ears.hear(cmd, msg.data.strip())

    def on_gesture(msg):
        if not (grid.on_grid(msg.person_x, msg.person_y)
                and grid.on_grid(msg.point_x, msg.point_y)):
            gesture_refusal('person (%d, %d) pointing at (%d, %d) is off the grid [%d, %d]; '
                            'ignored' % (msg.person_x, msg.person_y, msg.point_x, msg.point_y,
                                         grid.GRID_MIN, grid.GRID_MAX))
            return
        rospy.loginfo('/gesture: the person at (%d, %d) points at (%d, %d)', msg.person_x,
                      msg.person_y, msg.point_x, msg.point_y)
        person.saw_gesture((msg.person_x, msg.person_y), (msg.point_x, msg.point_y))
    rospy.Subscriber('/voice', String, on_voice, queue_size=100)
    rospy.Subscriber('/gesture', Gesture, on_gesture, queue_size=100)


def last_arrival_number():
    """The number of the last arrival in ``/all`` (0: none yet)."""
    report = rospy.get_param('/all', None)
    try:
        return int(report[4])
    except (TypeError, IndexError, ValueError, OverflowError):
        return 0


class OmniMotionController(object):
    """Drives the omnidirectional MiRo to ``/target_pos`` at ``rate`` Hz of ROS
    time, whatever its heading (the planar drive reads x, y in MiRo's frame);
    a new target replaces the old one at once. On arrival (within
    ``tolerance``) it stops, publishes ``/arrival`` and sets ``/all`` and
    ``/arrived`` (0 while moving, 1 once there), the original's parameters."""

    def __init__(self, kp=1.0, max_speed=1.0, tolerance=0.05, rate=20.0):
        self.kp, self.max_speed, self.tolerance = kp, max_speed, tolerance
        # pose: (position, yaw); arrivals are counted on from /all's (a respawn)
        self.target, self.pose, self.number = None, None, last_arrival_number() + 1
        self.cmd_pub = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
        self.arrival_pub = rospy.Publisher('/arrival', Float64MultiArray, queue_size=10)
        self.refuse = refusal_log('/target_pos')
        rospy.set_param('/arrived', 1)
        rospy.Subscriber('/odom', Odometry, self._on_odom, queue_size=1)
        rospy.Subscriber('/target_pos', Int64MultiArray, self._on_target, queue_size=10)
        rospy.Timer(rospy.Duration(1.0 / rate), self._tick, reset=True)  # survives time going back

    def _on_odom(self, msg):
        q = msg.pose.pose.orientation
        self.pose = (msg.pose.pose.position, yaw_of((q.x, q.y, q.z, q.w)))

    def _on_target(self, msg):
        target = grid.target_point(msg.data)
        if target is None:
            self.refuse('%s is not a grid point [x, y] in [%d, %d]; ignored'
                        % (list(msg.data)[:4], grid.GRID_MIN, grid.GRID_MAX))
            return
        self.target = target
        rospy.set_param('/arrived', 0)

    def _tick(self, _event):
        target, pose = self.target, self.pose
        if target is None or pose is None:
            return
        pose, yaw = pose
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
        twist.linear.x, twist.linear.y = world_to_body(
            *planar_velocity(pose.x, pose.y, target[0], target[1], self.kp, self.max_speed),
            yaw=yaw)
        self.cmd_pub.publish(twist)

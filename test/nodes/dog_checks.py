"""Helpers shared by the scenario-A checker nodes (not a test by itself)."""
import math
import threading
import time

import rospy
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState
from std_msgs.msg import String


class Watch(object):
    """Keeps the latest message of a topic and wakes waiters on each one."""

    def __init__(self, topic, cls):
        self.msg = None
        self.cond = threading.Condition()
        rospy.Subscriber(topic, cls, self._cb, queue_size=10)

    def _cb(self, msg):
        with self.cond:
            self.msg = msg
            self.cond.notify_all()
        self.on_message(msg)

    def on_message(self, msg):
        pass


def wait_until(predicate, ros_seconds, wall_limit=300.0):
    """Poll ``predicate`` every 0.05 s of ROS time; True once it holds."""
    end = rospy.Time.now() + rospy.Duration(ros_seconds)
    wall_end = time.monotonic() + wall_limit
    while not rospy.is_shutdown() and rospy.Time.now() < end and time.monotonic() < wall_end:
        if predicate():
            return True
        rospy.sleep(0.05)
    return predicate()


class DogObserver(object):
    """Everything a scenario-A checker looks at: states, poses, head."""

    def __init__(self):
        self.states = []            # (ros time, label)
        self.head_positions = []
        self.robot = Watch('/robot/odom', Odometry)
        self.ball = Watch('/ball/odom', Odometry)
        rospy.Subscriber('/robot/state', String, self._on_state, queue_size=10)
        rospy.Subscriber('/robot/joint_states', JointState, self._on_joints, queue_size=50)

    def _on_state(self, msg):
        self.states.append((rospy.Time.now(), msg.data))

    def _on_joints(self, msg):
        if 'head_joint' in msg.name:
            self.head_positions.append(msg.position[msg.name.index('head_joint')])

    def state(self):
        return self.states[-1][1] if self.states else None

    def robot_xy(self):
        p = self.robot.msg.pose.pose.position
        return p.x, p.y

    def ball_distance(self):
        if self.robot.msg is None or self.ball.msg is None:
            return float('inf')
        r, b = self.robot.msg.pose.pose.position, self.ball.msg.pose.pose.position
        return math.hypot(r.x - b.x, r.y - b.y)

    def head_reached(self, angle, tolerance):
        return any(abs(h - angle) <= tolerance for h in self.head_positions)

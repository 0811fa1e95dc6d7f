"""Who moves the ball: the automatic mover and a person at the shell.

* :class:`BallAutoMotion` (``move_ball_around.py``): random goal in the arena,
  wait, another, wait, disappear, wait, again; durations in ROS time. It
  pauses while ``/ball/auto`` (std_msgs/Bool, latched) is false.
* :class:`HumanBallCommands` (``human_commands.py``): ``/ball/command`` text
  (``go to X Y``, ``hide``, ``show``, ``auto``, ``stop``). Any command but
  ``auto`` pauses the automatic motion until ``auto``.
"""
import random
import threading

import actionlib
import rospy
from nav_msgs.msg import Odometry
from std_msgs.msg import Bool, String

from exp_assignment2.commands import parse_ball_command, parse_or_report
from exp_assignment2.msg import PlanningAction, PlanningGoal
from exp_assignment2.world import ARENA_GOAL_LIMIT

AUTO_TOPIC = '/ball/auto'


def ball_goal(x, y, z=0.0):
    goal = PlanningGoal()
    goal.target_pose.header.frame_id = 'odom'
    goal.target_pose.header.stamp = rospy.Time.now()
    goal.target_pose.pose.position.x = x
    goal.target_pose.pose.position.y = y
    goal.target_pose.pose.position.z = z
    goal.target_pose.pose.orientation.w = 1.0
    return goal


def connect_ball_client(timeout=30.0):
    client = actionlib.SimpleActionClient('/reaching_goal', PlanningAction)
    if not client.wait_for_server(rospy.Duration(timeout)):
        raise RuntimeError('no /reaching_goal action server after %.0f s' % timeout)
    return client


class BallAutoMotion(object):
    """The original's ball routine, pausable through ``/ball/auto``."""

    def __init__(self):
        self.rng = random.Random(rospy.get_param('~seed', 1))
        self.wait_time = float(rospy.get_param('~wait_time', 8.0))
        self.hidden_time = float(rospy.get_param('~hidden_time', 10.0))
        self.moves_per_round = int(rospy.get_param('~moves_per_round', 2))
        self.goal_timeout = float(rospy.get_param('~goal_timeout', 60.0))
        self.enabled = threading.Event()
        if rospy.get_param('~start_enabled', True):
            self.enabled.set()
        self.client = connect_ball_client()
        rospy.Subscriber(AUTO_TOPIC, Bool, self._on_auto, queue_size=10)

    def _on_auto(self, msg):
        if msg.data and not self.enabled.is_set():
            rospy.loginfo('move_ball_around: resumed')
            self.enabled.set()
        elif not msg.data and self.enabled.is_set():
            rospy.loginfo('move_ball_around: paused (a person moves the ball)')
            self.enabled.clear()
            self.client.cancel_goal()

    def random_point(self):
        return (self.rng.uniform(-ARENA_GOAL_LIMIT, ARENA_GOAL_LIMIT),
                self.rng.uniform(-ARENA_GOAL_LIMIT, ARENA_GOAL_LIMIT))

    def _wait(self, seconds):
        """Sleep in ROS time; False if paused or shut down meanwhile."""
        end = rospy.Time.now() + rospy.Duration(seconds)
        while rospy.Time.now() < end and self.enabled.is_set():
            rospy.sleep(min(0.5, seconds))
        return self.enabled.is_set() and not rospy.is_shutdown()

    def _move(self, x, y, z=0.0):
        if not self.enabled.is_set():
            return False
        self.client.send_goal(ball_goal(x, y, z))
        finished = self.client.wait_for_result(rospy.Duration(self.goal_timeout))
        if not finished:
            self.client.cancel_goal()
        return self.enabled.is_set()

    def run(self):
        while not rospy.is_shutdown():
            if not self.enabled.wait(timeout=1.0):
                continue
            for _ in range(self.moves_per_round):
                x, y = self.random_point()
                rospy.loginfo('move_ball_around: ball to (%.1f, %.1f)', x, y)
                if not (self._move(x, y) and self._wait(self.wait_time)):
                    break
            else:
                rospy.loginfo('move_ball_around: ball disappears')
                x, y = self.random_point()
                if self._move(x, y, -1.0):
                    self._wait(self.hidden_time)


class HumanBallCommands(object):
    """Turns ``/ball/command`` text into ball goals."""

    def __init__(self):
        self.client = connect_ball_client()
        self.auto_pub = rospy.Publisher(AUTO_TOPIC, Bool, queue_size=1, latch=True)
        self.position = None
        rospy.Subscriber('/ball/odom', Odometry, self._on_odom, queue_size=1)
        rospy.Subscriber('/ball/command', String, self._on_command, queue_size=10)

    def _on_odom(self, msg):
        self.position = msg.pose.pose.position

    def _on_command(self, msg):
        cmd = parse_or_report(parse_ball_command, msg.data,
                              lambda why: rospy.logerr('/ball/command: %s', why))
        if cmd is None:
            return
        rospy.loginfo('/ball/command: %s', msg.data.strip())
        if cmd.kind == 'auto':
            self.auto_pub.publish(Bool(True))
            return
        self.auto_pub.publish(Bool(False))
        if cmd.kind == 'go_to':
            self.client.send_goal(ball_goal(cmd.x, cmd.y))
        elif cmd.kind == 'stop':
            self.client.cancel_all_goals()
        elif cmd.kind in ('hide', 'show'):
            if self.position is None:
                rospy.logerr('/ball/command: %s: no ball odometry yet', cmd.kind)
                return
            x = max(-ARENA_GOAL_LIMIT, min(ARENA_GOAL_LIMIT, self.position.x))
            y = max(-ARENA_GOAL_LIMIT, min(ARENA_GOAL_LIMIT, self.position.y))
            self.client.send_goal(ball_goal(x, y, -1.0 if cmd.kind == 'hide' else 0.0))


def main_auto():
    rospy.init_node('move_ball_around')
    try:
        BallAutoMotion().run()
    except rospy.ROSInterruptException:
        pass    # Ctrl-C during a wait in ROS time: a normal end


def main_human():
    rospy.init_node('human_commands')
    HumanBallCommands()
    rospy.spin()

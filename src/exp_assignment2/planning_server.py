"""The two PlanningAction servers of scenario A: move the robot, move the ball.

Both validate the goal (finite, inside the arena), follow odometry at a fixed
rate of ROS time, report the original's feedback wording, stop on preemption
and abort with a clear text when the goal is bad, odometry stops or the goal
takes longer than ``~goal_timeout``.
"""
import math
import threading

import actionlib
import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from std_srvs.srv import SetBool

from exp_assignment2.control import ANGLE_ALIGNED, DONE, FEEDBACK, GO_STRAIGHT, GoToPoint, \
    planar_velocity
from exp_assignment2.msg import PlanningAction, PlanningFeedback, PlanningResult
from exp_assignment2.simulator import yaw_of
from exp_assignment2.world import ARENA_GOAL_LIMIT, in_arena


def goal_error(goal):
    """Why a goal cannot be executed, or None when it can."""
    pos = goal.target_pose.pose.position
    if not all(math.isfinite(v) for v in (pos.x, pos.y, pos.z)):
        return 'goal (%s, %s, %s) is not finite' % (pos.x, pos.y, pos.z)
    if not in_arena(pos.x, pos.y):
        return ('goal (%.2f, %.2f) is outside the arena: x and y must be in [-%g, %g]'
                % (pos.x, pos.y, ARENA_GOAL_LIMIT, ARENA_GOAL_LIMIT))
    return None


class OdomFollower(object):
    """Keeps the latest pose from an Odometry topic."""

    def __init__(self, topic):
        self.pose = None
        self.stamp = None
        self._lock = threading.Lock()
        rospy.Subscriber(topic, Odometry, self._on_odom, queue_size=1)

    def _on_odom(self, msg):
        with self._lock:
            self.pose = msg.pose.pose
            self.stamp = msg.header.stamp

    def wait_first(self, timeout):
        """Wait (ROS time) for the first message; True once there is one."""
        end = rospy.Time.now() + rospy.Duration(timeout)
        while self.pose is None and not rospy.is_shutdown() and rospy.Time.now() < end:
            rospy.sleep(0.05)
        return self.pose is not None

    def latest(self):
        with self._lock:
            return self.pose, self.stamp


class PlanningServer(object):
    """Shared action plumbing; subclasses give :meth:`control` and hooks."""

    def __init__(self, action_name, odom_topic, cmd_topic):
        self.rate_hz = float(rospy.get_param('~rate', 20.0))
        self.goal_timeout = float(rospy.get_param('~goal_timeout', 120.0))
        self.odom_timeout = float(rospy.get_param('~odom_timeout', 2.0))
        self.odom = OdomFollower(odom_topic)
        self.cmd_pub = rospy.Publisher(cmd_topic, Twist, queue_size=1)
        self.server = actionlib.SimpleActionServer(action_name, PlanningAction,
                                                   self.execute, auto_start=False)
        self.server.start()
        rospy.loginfo('%s: ready', action_name)
        self.name = action_name

    def feedback(self, stat, pose):
        fb = PlanningFeedback(stat=stat)
        if pose is not None:
            fb.position = pose
        self.server.publish_feedback(fb)

    def stop(self):
        self.cmd_pub.publish(Twist())

    def execute(self, goal):
        error = goal_error(goal)
        if error:
            rospy.logerr('%s: rejected: %s', self.name, error)
            self.server.set_aborted(PlanningResult(), error)
            return
        target = goal.target_pose.pose.position
        if not self.odom.wait_first(10.0):
            self.server.set_aborted(PlanningResult(), 'no odometry received')
            return
        if not self.begin(target):
            return
        rate = rospy.Rate(self.rate_hz)
        deadline = rospy.Time.now() + rospy.Duration(self.goal_timeout)
        while not rospy.is_shutdown():
            if self.server.is_preempt_requested():
                self.stop()
                self.server.set_preempted(PlanningResult(), 'preempted')
                return
            pose, stamp = self.odom.latest()
            now = rospy.Time.now()
            if pose is None or (now - stamp).to_sec() > self.odom_timeout:
                self.stop()
                text = 'no odometry for %.1f s' % self.odom_timeout
                rospy.logerr('%s: aborted: %s', self.name, text)
                self.server.set_aborted(PlanningResult(), text)
                return
            if now > deadline:
                self.stop()
                text = 'goal not reached within %.0f s' % self.goal_timeout
                rospy.logwarn('%s: aborted: %s', self.name, text)
                self.server.set_aborted(PlanningResult(), text)
                return
            if self.control(pose, target):
                self.stop()
                self.feedback(FEEDBACK[DONE], pose)
                self.server.set_succeeded(PlanningResult(), FEEDBACK[DONE])
                return
            try:
                rate.sleep()
            except rospy.ROSInterruptException:
                break           # shutting down: no traceback
        self.stop()

    def begin(self, target):
        """Prepare a goal; False when it was already answered."""
        return True

    def control(self, pose, target):
        """Publish one velocity command; return True when the target is reached."""
        raise NotImplementedError


class RobotPlanningServer(PlanningServer):
    """``/robot_reaching_goal``: turn towards the goal, then drive (z ignored)."""

    def __init__(self):
        self.ctrl = GoToPoint(
            dist_precision=float(rospy.get_param('~dist_precision', 0.1)),
            kp_a=float(rospy.get_param('~kp_a', 3.0)),
            kp_d=float(rospy.get_param('~kp_d', 0.2)),
            max_angular=float(rospy.get_param('~max_angular', 0.6)),
            max_linear=float(rospy.get_param('~max_linear', 0.6)))
        self.last_phase = None
        PlanningServer.__init__(self, '/robot_reaching_goal', '/robot/odom', '/robot/cmd_vel')

    def begin(self, target):
        self.ctrl.reset()
        self.last_phase = None
        return True

    def control(self, pose, target):
        cmd, phase = self.ctrl.update(pose.position.x, pose.position.y,
                                      yaw_of((pose.orientation.x, pose.orientation.y,
                                              pose.orientation.z, pose.orientation.w)),
                                      target.x, target.y)
        if phase == DONE:
            return True
        if phase == GO_STRAIGHT and self.last_phase != GO_STRAIGHT:
            self.feedback(ANGLE_ALIGNED, pose)
        self.last_phase = phase
        self.feedback(FEEDBACK[phase], pose)
        twist = Twist()
        twist.linear.x, twist.angular.z = cmd.linear, cmd.angular
        self.cmd_pub.publish(twist)
        return False


class BallPlanningServer(PlanningServer):
    """``/reaching_goal``: move the ball; z < 0 hides it, z >= 0 shows it again."""

    def __init__(self):
        self.kp = float(rospy.get_param('~kp_d', 0.5))
        self.max_speed = float(rospy.get_param('~max_speed', 2.0))
        self.precision = float(rospy.get_param('~dist_precision', 0.1))
        rospy.wait_for_service('/ball/set_visible', timeout=30.0)
        self.set_visible = rospy.ServiceProxy('/ball/set_visible', SetBool)
        PlanningServer.__init__(self, '/reaching_goal', '/ball/odom', '/ball/cmd_vel')

    def _show(self, visible):
        try:
            self.set_visible(visible)
        except rospy.ServiceException as exc:
            rospy.logerr('%s: cannot %s the ball: %s', self.name,
                         'show' if visible else 'hide', exc)
            return False
        return True

    def begin(self, target):
        if target.z < 0:
            if self._show(False):
                self.feedback('Ball hidden', None)
                self.server.set_succeeded(PlanningResult(), 'Ball hidden')
            else:
                self.server.set_aborted(PlanningResult(), 'the simulator did not hide the ball')
            return False
        if not self._show(True):      # idempotent: the ball may start hidden
            self.server.set_aborted(PlanningResult(), 'the simulator did not show the ball')
            return False
        return True

    def control(self, pose, target):
        dx, dy = target.x - pose.position.x, target.y - pose.position.y
        if math.hypot(dx, dy) <= self.precision:
            return True
        self.feedback(FEEDBACK[GO_STRAIGHT], pose)
        twist = Twist()
        twist.linear.x, twist.linear.y = planar_velocity(
            pose.position.x, pose.position.y, target.x, target.y, self.kp, self.max_speed)
        self.cmd_pub.publish(twist)
        return False


def main_robot():
    rospy.init_node('go_to_point_robot')
    RobotPlanningServer()
    rospy.spin()


def main_ball():
    rospy.init_node('go_to_point_ball')
    BallPlanningServer()
    rospy.spin()

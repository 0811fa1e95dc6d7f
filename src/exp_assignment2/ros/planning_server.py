"""The PlanningAction servers' ROS side: goals in, velocity commands out.

One control step per odometry message (an event, not a timer); a wait for
the next one also ends on preemption or shutdown, and on ``odom_timeout`` s of
silence (of the node's clock, which a jump of ROS time does not move): the
body is stopped until odometry comes back, with a WARN line, and the goal is
aborted only at its ``goal_timeout`` (a starved process on a loaded machine
misses 2 s of a fast simulator's odometry, seen in action_roundtrip). Goals
are checked by :func:`exp_assignment2.planning.goal_error` before they are
accepted: a refused goal is REJECTED with the reason as the status text and
one line (throttled by a :class:`~exp_assignment2.refusal.RefusalLog`), and
the goal under way goes on (:mod:`exp_assignment2.ros.action_server`).
"""
import threading

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from gazebo_msgs.msg import LinkState
from gazebo_msgs.srv import SetLinkState

from exp_assignment2.geometry import yaw_of
from exp_assignment2.msg import PlanningAction, PlanningFeedback, PlanningResult
from exp_assignment2.planning import REACHED, goal_error
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.ros.action_server import CheckedActionServer
from exp_assignment2.ros.log import refusal_log
from exp_assignment2.ros.robot_model import robot_name

HEIGHT_TIMEOUT = 10.0   # s of ROS time for the ball to take the goal's height


class OdomWatch(object):
    """The latest pose of an Odometry topic; each message notifies the clock."""

    def __init__(self, topic, clock):
        self.clock, self.pose, self.count = clock, None, 0
        self.lock = threading.Lock()
        rospy.Subscriber(topic, Odometry, self._on_odom, queue_size=1)

    def _on_odom(self, msg):
        with self.lock:
            self.pose, self.count = msg.pose.pose, self.count + 1
        self.clock.notify()

    def latest(self):
        with self.lock:
            return self.pose, self.count


class PlanningServer(object):
    """A SimpleActionServer driving one body; subclasses give the control step.

    :param uses_z: the goal's z is used (the ball's height) and so checked
    """

    def __init__(self, name, odom_topic, cmd_topic, clock, uses_z=False):
        self.name, self.clock, self.uses_z = name, clock, uses_z
        self.goal_timeout = float(rospy.get_param('~goal_timeout', 120.0))
        self.odom_timeout = float(rospy.get_param('~odom_timeout', 2.0))
        self.odom, self.odom_topic = OdomWatch(odom_topic, clock), odom_topic
        self.cmd_pub = rospy.Publisher(cmd_topic, Twist, queue_size=1)
        self.silence = RefusalLog(name, rospy.logwarn, period=10.0, what='silences')
        self.server = CheckedActionServer(name, PlanningAction, self.execute, self.goal_error,
                                          refusal_log(name), refusal_log(name + '/cancel'))
        self.server.register_preempt_callback(clock.notify)
        self.server.start()
        rospy.loginfo('%s: ready', name)

    def feedback(self, text, pose):
        self.server.publish_feedback(PlanningFeedback(stat=text, position=pose))

    def stop(self):
        self.cmd_pub.publish(Twist())

    def _abort(self, text, log=rospy.logwarn):
        self.stop()
        log('%s: aborted: %s', self.name, text)
        self.server.set_aborted(PlanningResult(), text)

    def goal_error(self, goal):
        """Why ``goal`` is refused, or None."""
        target = goal.target_pose.pose.position
        return goal_error(target.x, target.y, target.z if self.uses_z else None)

    def execute(self, goal):
        target = goal.target_pose.pose.position
        if not self.clock.wait_until(lambda: self.odom.latest()[0] is not None, 10.0):
            self._abort('no odometry on %s' % self.odom_topic, rospy.logerr)
            return
        if not self.begin(target):
            return
        deadline = self.clock.now() + self.goal_timeout
        while True:
            _, count = self.odom.latest()
            fresh = self.clock.wait_until(
                lambda: self.odom.latest()[1] != count or self.server.is_preempt_requested(),
                self.odom_timeout)
            if self.clock.is_shutdown():
                self.stop()
                self.server.set_aborted(PlanningResult(), 'the server is shutting down')
                return
            if self.server.is_preempt_requested():
                self.stop()
                self.server.set_preempted(PlanningResult(), 'preempted')
                return
            if self.clock.now() > deadline:
                self._abort('goal not reached within %.0f s' % self.goal_timeout)
                return
            if not fresh:
                self.stop()
                self.silence('no odometry on %s for %.1f s: the body stands still until it '
                             'comes back' % (self.odom_topic, self.odom_timeout))
                continue
            pose, _ = self.odom.latest()
            if self.control(pose, target):
                self.stop()
                self.feedback(REACHED, pose)
                self.server.set_succeeded(PlanningResult(), REACHED)
                return

    def begin(self, target):
        """Prepare a goal; False when it was already answered."""
        return True

    def control(self, pose, target):
        """Publish one velocity command; True when the target is reached."""
        raise NotImplementedError


class RobotPlanningServer(PlanningServer):
    """``/robot_reaching_goal``: turn towards the goal, then drive (z ignored)."""

    def __init__(self, controller, clock, sign):
        self.controller, self.sign = controller, sign
        PlanningServer.__init__(self, '/robot_reaching_goal', robot_name('odom'),
                                robot_name('cmd_vel'),
                                clock)

    def begin(self, target):
        self.controller.begin()
        return True

    def control(self, pose, target):
        q = pose.orientation
        (linear, angular), texts, done = self.controller.step(
            pose.position.x, pose.position.y, yaw_of((q.x, q.y, q.z, q.w)), target.x, target.y)
        if done:
            return True
        for text in texts:
            self.feedback(text, pose)
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, self.sign * angular
        self.cmd_pub.publish(twist)
        return False


class BallPlanningServer(PlanningServer):
    """``/reaching_goal``: the goal's z becomes the ball's height through
    Gazebo's ``/gazebo/set_link_state``, as the original's server did (below 0:
    under the ground; 20: far out of view), then the ball moves to (x, y)."""

    LINK = 'ball::ball_link'

    def __init__(self, controller, clock):
        self.controller = controller
        self.set_link_state = rospy.ServiceProxy('/gazebo/set_link_state', SetLinkState)
        PlanningServer.__init__(self, '/reaching_goal', '/ball/odom', '/ball/cmd_vel', clock,
                                uses_z=True)

    def begin(self, target):
        at = self.odom.latest()[0].position
        state = LinkState(link_name=self.LINK, reference_frame='world')
        state.pose.position.x, state.pose.position.y, state.pose.position.z = at.x, at.y, target.z
        state.pose.orientation.w = 1.0
        try:
            self.set_link_state.wait_for_service(5.0)
            answer = self.set_link_state(state)
        except (rospy.ROSException, rospy.ServiceException) as exc:
            self._abort('cannot set the ball\'s height: %s' % exc, rospy.logerr)
            return False
        if not answer.success:
            self._abort('the simulator refused the height: %s' % answer.status_message,
                        rospy.logerr)
            return False
        # one physics step does it; 10 s of ROS time leave room for a starved node
        at_height = self.clock.wait_until(
            lambda: abs(self.odom.latest()[0].position.z - target.z) < 1e-3
            or self.server.is_preempt_requested(), HEIGHT_TIMEOUT)
        if not at_height and not self.server.is_preempt_requested():
            self._abort('the ball did not reach height %.2f' % target.z, rospy.logerr)
            return False
        return True

    def control(self, pose, target):
        (vx, vy), texts, done = self.controller.step(pose.position.x, pose.position.y,
                                                     target.x, target.y)
        if done:
            return True
        for text in texts:
            self.feedback(text, pose)
        twist = Twist()
        twist.linear.x, twist.linear.y = vx, vy
        self.cmd_pub.publish(twist)
        return False

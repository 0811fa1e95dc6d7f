#!/usr/bin/env python3
"""The original assignment's robot server, go_to_point_robot.py, rebuilt from
what seed 000 documents of it: an actionlib SimpleActionServer
``/robot_reaching_goal`` (``exp_assignment2/PlanningAction``) that drives the
robot on ``/robot/cmd_vel`` from ``/robot/odom``, with the documented module
variables and constants:

    kp_a = -3.0, kp_d = 0.2, ub_a = 0.6, lb_a = -0.5, ub_d = 0.6,
    yaw_precision_ = pi/9, yaw_precision_2_ = pi/90, dist_precision_ = 0.1,
    state_ 0 = fix yaw, 1 = go straight ahead, 2 = done,

and the documented functions clbk_odom, change_state, normalize_angle,
fix_yaw, go_straight_ahead, done, planning, main. The bodies are the classic
go-to-point state machine those imply, in the original's style: module-level
state, an odom callback, and a ``rospy.Rate`` loop in the goal callback
(feedback "Fixing the yaw", "Angle aligned", "Target reached!").

kp_a is negative because the original course robot turns RIGHT on
+angular.z: with ``robot_model:=original`` a positive yaw error (goal to the
left) gives a negative angular.z, which turns it left. The seed lists no
lower speed bound, so the approach slows as kp_d * distance.
"""
import math

import actionlib
import rospy
from geometry_msgs.msg import Point, Pose, Twist
from nav_msgs.msg import Odometry

import exp_assignment2.msg

# robot state variables
position_ = Point()
pose_ = Pose()
yaw_ = 0
# machine state
state_ = 0
desired_position_ = Point()
desired_position_.z = 0
# parameters
yaw_precision_ = math.pi / 9  # +/- 20 degrees allowed while driving
yaw_precision_2_ = math.pi / 90  # +/- 2 degrees when turning on the spot
dist_precision_ = 0.1
kp_a = -3.0
kp_d = 0.2
ub_a = 0.6
lb_a = -0.5
ub_d = 0.6
z_back = 0.25
# publisher
pub = None
pubz = None
# action_server
act_s = None


def clbk_odom(msg):
    global position_, pose_, yaw_
    position_ = msg.pose.pose.position
    pose_ = msg.pose.pose
    # the original: tf.transformations.euler_from_quaternion(q)[2]; the same
    # yaw computed here, so the tests do not need python3-tf
    q = msg.pose.pose.orientation
    yaw_ = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def change_state(state):
    global state_
    state_ = state
    print('State changed to [%s]' % state_)


def normalize_angle(angle):
    if math.fabs(angle) > math.pi:
        angle = angle - (2 * math.pi * angle) / (math.fabs(angle))
    return angle


def bounded_angular(err_yaw):
    z = kp_a * err_yaw
    if z > ub_a:
        z = ub_a
    elif z < lb_a:
        z = lb_a
    return z


def fix_yaw(des_pos):
    desired_yaw = math.atan2(des_pos.y - position_.y, des_pos.x - position_.x)
    err_yaw = normalize_angle(desired_yaw - yaw_)
    twist_msg = Twist()
    if math.fabs(err_yaw) > yaw_precision_2_:
        twist_msg.angular.z = bounded_angular(err_yaw)
    pub.publish(twist_msg)
    # state change conditions
    if math.fabs(err_yaw) <= yaw_precision_2_:
        change_state(1)


def go_straight_ahead(des_pos):
    desired_yaw = math.atan2(des_pos.y - position_.y, des_pos.x - position_.x)
    err_yaw = normalize_angle(desired_yaw - yaw_)
    err_pos = math.sqrt(pow(des_pos.y - position_.y, 2) + pow(des_pos.x - position_.x, 2))
    if err_pos > dist_precision_:
        twist_msg = Twist()
        twist_msg.linear.x = kp_d * err_pos
        if twist_msg.linear.x > ub_d:
            twist_msg.linear.x = ub_d
        twist_msg.angular.z = bounded_angular(err_yaw)
        pub.publish(twist_msg)
    else:
        change_state(2)
    # state change conditions
    if math.fabs(err_yaw) > yaw_precision_:
        change_state(0)


def done():
    twist_msg = Twist()
    twist_msg.linear.x = 0
    twist_msg.angular.z = 0
    pub.publish(twist_msg)


def planning(goal):
    global state_, desired_position_, act_s
    desired_position_.x = goal.target_pose.pose.position.x
    desired_position_.y = goal.target_pose.pose.position.y
    state_ = 0
    rate = rospy.Rate(20)
    success = True
    feedback = exp_assignment2.msg.PlanningFeedback()
    result = exp_assignment2.msg.PlanningResult()
    while not rospy.is_shutdown():
        if act_s.is_preempt_requested():
            rospy.loginfo('Goal was preempted')
            done()
            act_s.set_preempted()
            success = False
            break
        elif state_ == 0:
            feedback.stat = "Fixing the yaw"
            feedback.position = pose_
            act_s.publish_feedback(feedback)
            fix_yaw(desired_position_)
        elif state_ == 1:
            feedback.stat = "Angle aligned"
            feedback.position = pose_
            act_s.publish_feedback(feedback)
            go_straight_ahead(desired_position_)
        elif state_ == 2:
            feedback.stat = "Target reached!"
            feedback.position = pose_
            act_s.publish_feedback(feedback)
            done()
            break
        else:
            rospy.logerr('Unknown state!')
        rate.sleep()
    if success:
        rospy.loginfo('Goal: Succeeded!')
        act_s.set_succeeded(result)


def main():
    global pub, act_s
    rospy.init_node('go_to_point_robot')
    pub = rospy.Publisher('/robot/cmd_vel', Twist, queue_size=1)
    rospy.Subscriber('/robot/odom', Odometry, clbk_odom)
    act_s = actionlib.SimpleActionServer('/robot_reaching_goal',
                                         exp_assignment2.msg.PlanningAction,
                                         planning, auto_start=False)
    act_s.start()
    rospy.spin()


if __name__ == '__main__':
    main()

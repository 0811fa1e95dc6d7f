#!/usr/bin/env python
"""A ball server written the way the template's was (a test fixture): the
/reaching_goal PlanningAction server that sets the ball's height through
Gazebo's /gazebo/set_link_state topic (link ball_link; z = 20 makes it
"disappear"), then drives it on /ball/cmd_vel with a proportional law on
/ball/odom, in a loop paced by rospy.Rate."""
import math

import actionlib
import rospy
from gazebo_msgs.msg import LinkState
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

import exp_assignment2.msg

position_ = None
pub = None
pubz = None
act_s = None


def clbk_odom(msg):
    global position_
    position_ = msg.pose.pose.position


def planning(goal):
    target = goal.target_pose.pose.position
    while position_ is None and not rospy.is_shutdown():
        rospy.sleep(0.1)
    link_state = LinkState()
    link_state.link_name = "ball_link"
    link_state.pose.position.x = position_.x
    link_state.pose.position.y = position_.y
    link_state.pose.position.z = target.z
    link_state.reference_frame = "world"
    pubz.publish(link_state)
    rate = rospy.Rate(20)
    while not rospy.is_shutdown():
        if act_s.is_preempt_requested():
            pub.publish(Twist())
            act_s.set_preempted()
            return
        err_x, err_y = target.x - position_.x, target.y - position_.y
        if math.sqrt(err_x ** 2 + err_y ** 2) < 0.1:
            break
        twist = Twist()
        twist.linear.x = max(-0.8, min(0.8, 1.0 * err_x))
        twist.linear.y = max(-0.8, min(0.8, 1.0 * err_y))
        pub.publish(twist)
        rate.sleep()
    pub.publish(Twist())
    act_s.set_succeeded(exp_assignment2.msg.PlanningResult())


def main():
    global pub, pubz, act_s
    rospy.init_node('go_to_point_ball')
    pub = rospy.Publisher('/ball/cmd_vel', Twist, queue_size=1)
    pubz = rospy.Publisher('/gazebo/set_link_state', LinkState, queue_size=1)
    rospy.Subscriber('/ball/odom', Odometry, clbk_odom)
    act_s = actionlib.SimpleActionServer('/reaching_goal', exp_assignment2.msg.PlanningAction,
                                         planning, auto_start=False)
    act_s.start()
    rospy.spin()


if __name__ == '__main__':
    main()

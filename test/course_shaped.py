"""A submission shaped like a real class's, for the grader's benchmark
(bench/grade.py): the fixture dog (test/grading_fixtures.py) with the course
robot's camera, Gazebo's window and a course-shaped node."""
import os

from grading_fixtures import DOG, _package, _replace

# A submission shaped like a real class's (the benchmark's, bench/grade.py):
# the course robot's 800 x 800 camera at 30 Hz, Gazebo's window (gui true), a
# node that decodes, blurs and searches every frame and shows it with the
# circle drawn, as the template's does, and a SMACH state machine driving the dog.
COURSE_SHAPED = r"""#!/usr/bin/env python
import numpy as np
import cv2
import rospy
import smach
from geometry_msgs.msg import Twist
from sensor_msgs.msg import CompressedImage
from std_msgs.msg import Float64

greenLower = (50, 50, 20)
greenUpper = (70, 255, 255)


class BallTracker(object):
    def __init__(self):
        self.ball = None        # (offset from the centre, radius), in image widths
        self.subscriber = rospy.Subscriber('/robot/camera1/image_raw/compressed',
                                           CompressedImage, self.callback, queue_size=1,
                                           buff_size=2 ** 24)

    def callback(self, ros_data):
        np_arr = np.frombuffer(ros_data.data, np.uint8)
        image_np = cv2.imdecode(np_arr, cv2.IMREAD_COLOR)
        blurred = cv2.GaussianBlur(image_np, (11, 11), 0)
        hsv = cv2.cvtColor(blurred, cv2.COLOR_BGR2HSV)
        mask = cv2.inRange(hsv, greenLower, greenUpper)
        mask = cv2.erode(mask, None, iterations=2)
        mask = cv2.dilate(mask, None, iterations=2)
        cnts = cv2.findContours(mask.copy(), cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)[-2]
        ball = None
        if len(cnts) > 0:
            c = max(cnts, key=cv2.contourArea)
            ((x, y), radius) = cv2.minEnclosingCircle(c)
            if radius > 10:
                cv2.circle(image_np, (int(x), int(y)), int(radius), (0, 255, 255), 2)
                ball = (x / image_np.shape[1] - 0.5, radius / image_np.shape[1])
        self.ball = ball
        cv2.imshow('window', image_np)
        cv2.waitKey(2)


class Normal(smach.State):
    '''Turn on the spot until the ball is in view.'''
    def __init__(self, tracker, cmd):
        smach.State.__init__(self, outcomes=['ball', 'stop'])
        self.tracker, self.cmd = tracker, cmd

    def execute(self, userdata):
        rate = rospy.Rate(10)
        while not rospy.is_shutdown():
            if self.tracker.ball is not None:
                return 'ball'
            twist = Twist()
            twist.angular.z = -0.5
            self.cmd.publish(twist)
            rate.sleep()
        return 'stop'


class Play(smach.State):
    '''Go to the ball, then look left and right at it; lost: back to NORMAL.'''
    def __init__(self, tracker, cmd, head):
        smach.State.__init__(self, outcomes=['played', 'lost', 'stop'])
        self.tracker, self.cmd, self.head = tracker, cmd, head

    def execute(self, userdata):
        rate = rospy.Rate(10)
        lost = 0
        while not rospy.is_shutdown():
            ball = self.tracker.ball
            twist = Twist()
            if ball is None:
                lost += 1
                if lost > 20:
                    return 'lost'
            else:
                lost = 0
                offset, radius = ball
                twist.angular.z = 2.0 * offset
                twist.linear.x = 0.6 if radius < 0.2 else 0.0
                if radius >= 0.2 and abs(offset) < 0.1:
                    self.cmd.publish(Twist())
                    start = rospy.Time.now()
                    while not rospy.is_shutdown() and (rospy.Time.now() - start).to_sec() < 8:
                        elapsed = (rospy.Time.now() - start).to_sec()
                        self.head.publish(Float64(0.9 if elapsed % 8 < 4 else -0.9))
                        rate.sleep()
                    self.head.publish(Float64(0.0))
                    return 'played'
            self.cmd.publish(twist)
            rate.sleep()
        return 'stop'


def main():
    rospy.init_node('state_machine')
    cmd = rospy.Publisher('/robot/cmd_vel', Twist, queue_size=1)
    head = rospy.Publisher('/robot/joint_head_controller/command', Float64, queue_size=1)
    tracker = BallTracker()
    sm = smach.StateMachine(outcomes=['done'])
    with sm:
        smach.StateMachine.add('NORMAL', Normal(tracker, cmd),
                               transitions={'ball': 'PLAY', 'stop': 'done'})
        smach.StateMachine.add('PLAY', Play(tracker, cmd, head),
                               transitions={'played': 'NORMAL', 'lost': 'NORMAL', 'stop': 'done'})
    sm.execute()


if __name__ == '__main__':
    main()
"""


def make_course_shaped(dest):
    """The dog as a class hands it in (see COURSE_SHAPED), at ``dest``."""
    _package(dest)
    _replace(dest, DOG, COURSE_SHAPED)
    launch = os.path.join(dest, 'launch', 'gazebo_world.launch')
    with open(launch) as f:
        text = f.read()
    with open(launch, 'w') as f:        # Gazebo's window, as the course's launch file had
        f.write(text.replace('<arg name="gui" value="false"/>', '<arg name="gui" value="true"/>'))
    path = os.path.join(dest, 'urdf', 'robot.gazebo')
    with open(path) as f:
        text = f.read()
    shaped = text.replace('<update_rate>15.0</update_rate>', '<update_rate>30.0</update_rate>') \
        .replace('<width>320</width>', '<width>800</width>') \
        .replace('<height>240</height>', '<height>800</height>')
    assert shaped.count('800') == 2 and '30.0' in shaped
    with open(path, 'w') as f:
        f.write(shaped)
    return dest

#!/usr/bin/env python3
"""Does the original's 'disappear' work: a PlanningAction goal to
/reaching_goal (the package's go_to_point_ball.py) with z = 20 makes the ball
undetectable in the robot's camera, and a later goal with z = 0.5 brings it
back, in front of the robot?

"Detectable" is decided by the original's own pipeline (seed 000's
robot_to_ball / state_machine callbacks: blur 11x11, HSV, inRange
(50, 50, 20)-(70, 255, 255), erode x2, dilate x2, largest external contour,
minimum enclosing circle, moments; a ball is seen when radius > 10 px), run
on camera frames stamped after each goal succeeded. The robot stays at its
spawn pose (-5, 7) facing -x; the ball is first put 1.5 m in front of it.
A ball that is not lifted (or lifted but still in view) fails this.
"""
import threading
import unittest

import cv2
import numpy as np
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from sensor_msgs.msg import CompressedImage

from checks import Pose, SimpleClient, clock, finished, wait_until
from exp_assignment2.msg import PlanningAction
from exp_assignment2.planning import make_goal

IN_FRONT = (-6.5, 7.0)      # 1.5 m ahead of the robot at its spawn pose
FRAMES = 10                 # frames looked at after each goal
CENTRE_TOLERANCE = 80       # px: "in front of the robot" (800 px image)
STATES = {getattr(GoalStatus, n): n for n in ('PENDING', 'ACTIVE', 'PREEMPTED', 'SUCCEEDED',
                                              'ABORTED', 'REJECTED', 'RECALLED', 'LOST')}


def original_detection(jpeg):
    """The original's pipeline: (centre, radius) of the ball, or None when it
    sees no contour with radius > 10 px."""
    image_np = cv2.imdecode(np.frombuffer(jpeg, np.uint8), cv2.IMREAD_COLOR)
    blurred = cv2.GaussianBlur(image_np, (11, 11), 0)
    hsv = cv2.cvtColor(blurred, cv2.COLOR_BGR2HSV)
    mask = cv2.inRange(hsv, (50, 50, 20), (70, 255, 255))
    mask = cv2.erode(mask, None, iterations=2)
    mask = cv2.dilate(mask, None, iterations=2)
    cnts = cv2.findContours(mask.copy(), cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
    cnts = cnts[0] if len(cnts) == 2 else cnts[1]
    if len(cnts) == 0:
        return None
    c = max(cnts, key=cv2.contourArea)
    (_, radius) = cv2.minEnclosingCircle(c)
    M = cv2.moments(c)
    if radius <= 10 or M["m00"] == 0:
        return None
    return (int(M["m10"] / M["m00"]), int(M["m01"] / M["m00"])), radius


class Frames(object):
    """Camera frames stamped after a given ROS time, collected on request
    (only then are they kept)."""

    def __init__(self, topic):
        self.lock = threading.Lock()
        self.after, self.frames = None, []
        rospy.Subscriber(topic, CompressedImage, self._cb, queue_size=5, buff_size=2 ** 24)

    def _cb(self, msg):
        with self.lock:
            if self.after is not None and msg.header.stamp.to_sec() > self.after:
                self.frames.append(msg)
        clock().notify()

    def collect(self, after, count, ros_seconds=10.0):
        with self.lock:
            self.after, self.frames = after, []
        ok = wait_until(lambda: len(self.frames) >= count, ros_seconds)
        with self.lock:
            self.after, frames = None, list(self.frames)
        assert ok, 'only %d camera frames in %.0f s' % (len(frames), ros_seconds)
        return frames[:count]


class TestOriginalBall(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_original_ball')
        clock().wait_for_time()
        cls.ball = Pose('/ball/odom')
        cls.frames = Frames('/robot/camera1/image_raw/compressed')
        cls.client = SimpleClient('/reaching_goal', PlanningAction)
        assert cls.client.wait_for_server(rospy.Duration(60)), 'no /reaching_goal'

    def ball_goal(self, z):
        """Send the ball to IN_FRONT at height z; the detections in the frames
        stamped after the goal succeeded."""
        self.client.send_goal(make_goal(IN_FRONT[0], IN_FRONT[1], z))
        self.assertTrue(finished(self.client, 30.0), 'z = %g: no result' % z)
        state = self.client.get_state()
        self.assertEqual(state, GoalStatus.SUCCEEDED, 'z = %g: the goal ended %s (%s)' % (
            z, STATES.get(state, state), self.client.get_goal_status_text()))
        # the world shows the height once the ball's odometry does (a server that
        # sets it on the set_link_state topic may finish before that message lands)
        self.assertTrue(wait_until(lambda: abs(self.ball.msg.pose.pose.position.z - z) < 1e-3,
                                   5.0), 'z = %g: the ball never got there' % z)
        done = self.ball.msg.header.stamp.to_sec()
        seen = [original_detection(f.data) for f in self.frames.collect(done, FRAMES)]
        print('[check_original_ball] z = %g: ball at %s; %d of %d frames see it%s'
              % (z, tuple(round(v, 2) for v in self.ball.xyzyaw()[:3]),
                 sum(s is not None for s in seen), len(seen),
                 ''.join(' (centre %s, radius %.1f px)' % s for s in seen[-1:] if s)))
        return seen

    def assert_in_front(self, seen, what):
        self.assertTrue(all(s is not None for s in seen), '%s: not seen in every frame' % what)
        for (cx, _), radius in seen:
            self.assertLess(abs(cx - 400), CENTRE_TOLERANCE, '%s: centre x = %d' % (what, cx))

    def test_z20_hides_the_ball_and_z05_brings_it_back(self):
        self.assert_in_front(self.ball_goal(0.5), 'placed in front')
        hidden = self.ball_goal(20.0)
        seen = [s for s in hidden if s is not None]
        self.assertEqual(len(seen), 0, 'z = 20: the original still sees the ball in %d of %d '
                         'frames (centre %s, radius %.1f px)' % ((len(seen), len(hidden)) + (
                             seen[-1] if seen else (None, 0.0))))
        self.assert_in_front(self.ball_goal(0.5), 'back at z = 0.5')


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_original_ball', TestOriginalBall)

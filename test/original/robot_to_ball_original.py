#!/usr/bin/env python3
"""The original assignment's ball follower, robot_to_ball.py, as seed 000
documents it (class ``image_feature``, its ``callback``), written again for
the tests: same topics, same vision, same control law, same constants.

- subscribes to ``/robot/camera1/image_raw/compressed`` (queue_size 1) and
  publishes ``/robot/cmd_vel``, absolute names as in the original;
- vision: Gaussian blur 11x11, BGR->HSV, inRange (50, 50, 20)-(70, 255, 255),
  erode x2, dilate x2, external contours, the largest one, its minimum
  enclosing circle and its centroid (moments);
- control: with a contour whose radius > 10 px,
  ``angular.z = 0.002*(center[0]-400)`` and ``linear.x = -0.01*(radius-100)``;
  with no contour at all, ``angular.z = 0.5`` (turn and search); a contour of
  radius <= 10 px publishes nothing, as in the original.

It is written for the original course robot (``robot_model:=original``),
on which +angular.z turns right: a ball right of centre gives a positive
angular.z and the robot turns towards it.

Differences from the listing, none of which changes what is published:
``cv2.imshow('window', ...)`` / ``cv2.waitKey(2)`` are left out (they need a
display and abort a headless process; the tests run headless), so are the
circles drawn on the frame for that window; ``np.frombuffer`` replaces the
deprecated ``np.fromstring``; imutils' ``grab_contours`` is a two-line
function here, so the tests do not need imutils.
"""
import sys

import cv2
import numpy as np
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import CompressedImage

VERBOSE = False


def grab_contours(cnts):
    """imutils.grab_contours: the contour list of cv2.findContours' result
    (OpenCV 2/4 return 2 values, OpenCV 3 returns 3)."""
    return cnts[0] if len(cnts) == 2 else cnts[1]


class image_feature:

    def __init__(self):
        '''Initialize ros publisher, ros subscriber'''
        # kept as in the original; the callback does not publish on it
        self.image_pub = rospy.Publisher("/output/image_raw/compressed",
                                         CompressedImage, queue_size=1)
        self.vel_pub = rospy.Publisher("/robot/cmd_vel",
                                       Twist, queue_size=1)
        self.subscriber = rospy.Subscriber("/robot/camera1/image_raw/compressed",
                                           CompressedImage, self.callback, queue_size=1)

    def callback(self, ros_data):
        '''Callback function of subscribed topic.
        Here images get converted and features detected'''
        if VERBOSE:
            print('received image of type: "%s"' % ros_data.format)

        np_arr = np.frombuffer(ros_data.data, np.uint8)
        image_np = cv2.imdecode(np_arr, cv2.IMREAD_COLOR)

        greenLower = (50, 50, 20)
        greenUpper = (70, 255, 255)

        blurred = cv2.GaussianBlur(image_np, (11, 11), 0)
        hsv = cv2.cvtColor(blurred, cv2.COLOR_BGR2HSV)
        mask = cv2.inRange(hsv, greenLower, greenUpper)
        mask = cv2.erode(mask, None, iterations=2)
        mask = cv2.dilate(mask, None, iterations=2)
        cnts = cv2.findContours(mask.copy(), cv2.RETR_EXTERNAL,
                                cv2.CHAIN_APPROX_SIMPLE)
        cnts = grab_contours(cnts)
        center = None
        # only proceed if at least one contour was found
        if len(cnts) > 0:
            # the largest contour: its minimum enclosing circle and centroid
            c = max(cnts, key=cv2.contourArea)
            ((x, y), radius) = cv2.minEnclosingCircle(c)
            M = cv2.moments(c)
            center = (int(M["m10"] / M["m00"]), int(M["m01"] / M["m00"]))

            # only proceed if the radius meets a minimum size
            if radius > 10:
                vel = Twist()
                vel.angular.z = 0.002*(center[0]-400)
                vel.linear.x = -0.01*(radius-100)
                self.vel_pub.publish(vel)
        else:
            vel = Twist()
            vel.angular.z = 0.5
            self.vel_pub.publish(vel)
        # (the original showed the frame here: cv2.imshow('window', image_np);
        # cv2.waitKey(2) -- left out, it needs a display)


def main(args):
    '''Initializes and cleanup ros node'''
    rospy.init_node('image_feature', anonymous=True)
    image_feature()
    try:
        rospy.spin()
    except KeyboardInterrupt:
        print("Shutting down ROS Image feature detector module")


if __name__ == '__main__':
    main(sys.argv)

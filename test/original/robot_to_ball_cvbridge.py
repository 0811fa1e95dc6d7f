#!/usr/bin/env python
"""A student's variant of the original's ball follower, in the shape many
solutions took (a test fixture): the raw camera image through cv_bridge
instead of the JPEG stream, the ROS-relative topic names of a node started
in the robot's namespace, the original's vision and control law. It
needs ``<robot ns>/camera1/image_raw`` (sensor_msgs/Image) and Debian's
cv_bridge (original-env installs python3-cv-bridge)."""
import cv2
import rospy
from cv_bridge import CvBridge, CvBridgeError
from geometry_msgs.msg import Twist
from sensor_msgs.msg import Image


class image_feature:

    def __init__(self):
        self.bridge = CvBridge()
        self.vel_pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        self.subscriber = rospy.Subscriber("camera1/image_raw", Image, self.callback,
                                           queue_size=1, buff_size=2 ** 24)

    def callback(self, data):
        try:
            image_np = self.bridge.imgmsg_to_cv2(data, "bgr8")
        except CvBridgeError as e:
            print(e)
            return
        blurred = cv2.GaussianBlur(image_np, (11, 11), 0)
        hsv = cv2.cvtColor(blurred, cv2.COLOR_BGR2HSV)
        mask = cv2.inRange(hsv, (50, 50, 20), (70, 255, 255))
        mask = cv2.erode(mask, None, iterations=2)
        mask = cv2.dilate(mask, None, iterations=2)
        cnts = cv2.findContours(mask.copy(), cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
        cnts = cnts[0] if len(cnts) == 2 else cnts[1]
        if len(cnts) > 0:
            c = max(cnts, key=cv2.contourArea)
            ((x, y), radius) = cv2.minEnclosingCircle(c)
            M = cv2.moments(c)
            center = (int(M["m10"] / M["m00"]), int(M["m01"] / M["m00"]))
            if radius > 10:
                vel = Twist()
                vel.angular.z = 0.002*(center[0]-400)
                vel.linear.x = -0.01*(radius-100)
                self.vel_pub.publish(vel)
        else:
            vel = Twist()
            vel.angular.z = 0.5
            self.vel_pub.publish(vel)


if __name__ == '__main__':
    rospy.init_node('image_feature', anonymous=True)
    image_feature()
    rospy.spin()

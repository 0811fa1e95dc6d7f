"""The dog's senses and muscles: ROS glue used by its states and followers.

:class:`BallWatcher` decodes each camera frame, detects the ball, publishes the
annotated view on ``/output/image_raw/compressed`` (only while someone
listens) and, while a servo is attached, sends the visual-servo command in the
same callback, so a frame becomes a ``/robot/cmd_vel`` without waiting for a
loop. :class:`ImageWindow` is the optional display (``gui:=true``).
"""
import threading

import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import CompressedImage

from exp_assignment2.control import visual_servo
from exp_assignment2.vision import BallDetector, annotate, decode_jpeg, encode_jpeg

CAMERA_TOPIC = '/robot/camera1/image_raw/compressed'
OUTPUT_TOPIC = '/output/image_raw/compressed'


class ImageWindow(object):
    """Shows the latest annotated frame in an OpenCV window on its own thread."""

    def __init__(self, title='exp_assignment2 camera'):
        import cv2
        self.cv2, self.title = cv2, title
        self.frame = None
        self.new_frame = threading.Event()
        threading.Thread(target=self._loop, daemon=True).start()

    def show(self, bgr):
        self.frame = bgr
        self.new_frame.set()

    def _loop(self):
        while not rospy.is_shutdown():
            if self.new_frame.wait(0.1):
                self.new_frame.clear()
                self.cv2.imshow(self.title, self.frame)
            self.cv2.waitKey(1)


class BallFollower(object):
    """The visual servo: frame in, velocity out; turns in place when no ball."""

    def __init__(self, cmd_pub, search_rate=0.5):
        self.cmd_pub = cmd_pub
        self.target_radius_ratio = float(rospy.get_param('~target_radius_ratio', 0.3))
        self.max_linear = float(rospy.get_param('~max_linear', 0.8))
        self.max_angular = float(rospy.get_param('~max_angular', 1.0))
        self.search_rate = search_rate
        self.last_cmd = Twist()

    def on_frame(self, ball, width):
        twist = Twist()
        if ball is None:
            twist.angular.z = self.search_rate
        else:
            cmd = visual_servo(ball.cx, ball.radius, width, self.target_radius_ratio,
                               max_angular=self.max_angular, max_linear=self.max_linear)
            twist.linear.x, twist.angular.z = cmd.linear, cmd.angular
        self.last_cmd = twist
        self.cmd_pub.publish(twist)


class BallWatcher(object):
    """Camera in; the latest ball sighting out; annotated view; optional servo."""

    def __init__(self, gui=False):
        self.detector = BallDetector(float(rospy.get_param('~min_radius_at_800', 10.0)))
        self.lock = threading.Condition()
        self.ball, self.ball_stamp, self.frame_stamp = None, None, None
        self.width = None
        self.servo = None
        self.window = ImageWindow() if gui else None
        self.output_pub = rospy.Publisher(OUTPUT_TOPIC, CompressedImage, queue_size=1)
        rospy.Subscriber(CAMERA_TOPIC, CompressedImage, self._on_image, queue_size=1,
                         buff_size=2 ** 22)

    def attach(self, servo):
        """Let ``servo.on_frame(ball, width)`` act on every frame (None detaches)."""
        with self.lock:
            self.servo = servo

    def _on_image(self, msg):
        bgr = decode_jpeg(msg.data)
        if bgr is None:
            rospy.logwarn_throttle(10, 'camera: a frame could not be decoded')
            return
        ball = self.detector.detect(bgr)
        with self.lock:
            self.width = bgr.shape[1]
            self.frame_stamp = msg.header.stamp
            self.ball = ball
            if ball is not None:
                self.ball_stamp = msg.header.stamp
            servo = self.servo
            self.lock.notify_all()
        if servo is not None:
            servo.on_frame(ball, bgr.shape[1])
        if self.output_pub.get_num_connections() > 0 or self.window is not None:
            annotate(bgr, ball)
            if self.window is not None:
                self.window.show(bgr)
            if self.output_pub.get_num_connections() > 0:
                out = CompressedImage(header=msg.header, format='bgr8; jpeg compressed bgr8',
                                      data=encode_jpeg(bgr))
                self.output_pub.publish(out)

    def seen_since(self, stamp):
        """True when the ball was in a frame stamped at or after ``stamp``."""
        with self.lock:
            return self.ball_stamp is not None and self.ball_stamp >= stamp

    def seen_within(self, now, seconds):
        """True when the ball was in a frame at most ``seconds`` before ``now``."""
        with self.lock:
            return self.ball_stamp is not None and (now - self.ball_stamp).to_sec() <= seconds

    def last_seen(self):
        with self.lock:
            return self.ball_stamp

    def wait_for_ball(self, timeout):
        """Block until a frame shows the ball or ``timeout`` (wall s); True if seen."""
        with self.lock:
            return self.lock.wait_for(lambda: self.ball is not None, timeout)

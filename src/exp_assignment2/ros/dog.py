"""The dog's body and eyes over ROS (scenario A).

:class:`RosDogBody` publishes ``/robot/cmd_vel`` and the head command and
sends robot goals; :class:`RosDogEyes` decodes each camera frame, detects the
ball, runs the attached servo in the same callback (a frame becomes a
command without waiting for a loop), notifies the clock, and publishes the
annotated view on ``/output/image_raw/compressed`` only while someone listens.
"""
import threading

import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import CompressedImage
from std_msgs.msg import Float64

from exp_assignment2.ros.frames import FrameDecoder
from exp_assignment2.vision import BallDetector, annotate, encode_jpeg

CAMERA_TOPIC = '/robot/camera1/image_raw/compressed'
OUTPUT_TOPIC = '/output/image_raw/compressed'
CMD_TOPIC = '/robot/cmd_vel'
HEAD_TOPIC = '/robot/joint_position_controller/command'
HOLD_PERIOD = 0.1   # s: a held command is repeated so the drive's cmd_timeout keeps it


class CommandPublisher(object):
    """``/robot/cmd_vel`` in REP 103 terms, whatever the robot's wiring; a
    non-zero command is held (repeated) until the next one."""

    def __init__(self, sign, topic=CMD_TOPIC):
        self.sign = sign
        self.pub = rospy.Publisher(topic, Twist, queue_size=1)
        self.held, self.last = None, 0.0
        self.lock = threading.Lock()
        rospy.Timer(rospy.Duration(HOLD_PERIOD), self._hold, reset=True)  # survives time going back

    def drive(self, linear, angular):
        with self.lock:
            self.held = (linear, angular) if (linear or angular) else None
        self._publish(linear, angular)

    def stop(self):
        self.drive(0.0, 0.0)

    def _publish(self, linear, angular):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, self.sign * angular
        self.last = rospy.get_time()
        try:
            self.pub.publish(twist)
        except rospy.ROSException:
            if not rospy.is_shutdown():   # a frame arriving while the node stops: no trace
                raise

    def _hold(self, _event):
        with self.lock:
            held = self.held
        since = rospy.get_time() - self.last
        if held is not None and not 0.0 <= since < HOLD_PERIOD * 0.9:   # < 0: time went back
            self._publish(*held)


class RosDogBody(CommandPublisher):
    """:class:`~exp_assignment2.behaviour.interfaces.DogBody` over ROS."""

    def __init__(self, sign, robot_client):
        CommandPublisher.__init__(self, sign)
        self.robot = robot_client
        self.head_pub = rospy.Publisher(HEAD_TOPIC, Float64, queue_size=1, latch=True)

    def head(self, angle):
        self.head_pub.publish(Float64(angle))

    def go_to(self, x, y):
        return self.robot.go_to(x, y)


class ImageWindow(object):
    """The optional display (``gui:=true``): OpenCV windows are drawn from
    one thread only (Qt's rule), this one."""

    def __init__(self, title='exp_assignment2 camera'):
        import cv2
        self.cv2, self.title = cv2, title
        self.frame, self.new_frame = None, threading.Event()
        threading.Thread(target=self._loop, name='window', daemon=True).start()

    def show(self, bgr):
        self.frame = bgr
        self.new_frame.set()

    def _loop(self):
        while not rospy.is_shutdown():
            if self.new_frame.wait(0.1):
                self.new_frame.clear()
                self.cv2.imshow(self.title, self.frame)
            self.cv2.waitKey(1)


class RosDogEyes(object):
    """:class:`~exp_assignment2.behaviour.interfaces.DogEyes` over ROS."""

    def __init__(self, clock, min_radius_at_800=10.0, gui=False):
        self.clock = clock
        self.detector = BallDetector(min_radius_at_800)
        self.seen, self.servo = None, None
        self.window = ImageWindow() if gui else None
        self.output_pub = rospy.Publisher(OUTPUT_TOPIC, CompressedImage, queue_size=1)
        self.decode = FrameDecoder(CAMERA_TOPIC)
        rospy.Subscriber(CAMERA_TOPIC, CompressedImage, self._on_image, queue_size=1,
                         buff_size=2 ** 24)

    def last_seen(self):
        return self.seen

    def follow(self, servo):
        self.servo = servo

    def _on_image(self, msg):
        bgr = self.decode(msg)
        if bgr is None:
            return
        ball = self.detector.detect(bgr)
        if ball is not None:
            self.seen = self.clock.from_source(msg.header.stamp.to_sec())
        servo = self.servo
        if servo is not None:
            servo(ball, bgr.shape[1])
        self.clock.notify()
        wanted = self.output_pub.get_num_connections() > 0
        if wanted or self.window is not None:
            annotate(bgr, ball)
            if self.window is not None:
                self.window.show(bgr)
            if wanted:
                self.output_pub.publish(CompressedImage(
                    header=msg.header, format='bgr8; jpeg compressed bgr8',
                    data=encode_jpeg(bgr)))

"""The dog's body and eyes over ROS (scenario A).

:class:`RosDogBody` publishes ``<robot ns>/cmd_vel`` (``/robot`` unless the
node's ``~robot_ns`` says otherwise) and the head command and
sends robot goals; :class:`RosDogEyes` decodes each camera frame, detects the
ball, runs the attached servo in the same callback (a frame becomes a
command without waiting for a loop), notifies the clock, and publishes the
annotated view on ``/output/image_raw/compressed`` only while someone listens.
"""
import threading

import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import CompressedImage
from std_msgs.msg import Float64, Header

from exp_assignment2.ros.frames import FrameDecoder
from exp_assignment2.ros.robot_model import robot_name
from exp_assignment2.vision import BallDetector, annotate, encode_jpeg, vision_scale

CAMERA_TOPIC = 'camera1/image_raw/compressed'      # in the robot's namespace
FRAME_DONE_TOPIC = 'camera1/frame_done'     # each frame's header once it is dealt with
OUTPUT_TOPIC = '/output/image_raw/compressed'
CMD_TOPIC = 'cmd_vel'
HEAD_TOPIC = 'joint_position_controller/command'
HOLD_PERIOD = 0.1   # s: a held command is repeated so the drive's cmd_timeout keeps it


class CommandPublisher(object):
    """``<robot ns>/cmd_vel`` in REP 103 terms, whatever the robot's wiring; a
    non-zero command is held (repeated) until the next one."""

    def __init__(self, sign, topic=CMD_TOPIC):
        self.sign = sign
        self.pub = rospy.Publisher(robot_name(topic), Twist, queue_size=1)
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
            if not rospy.core.is_shutdown_requested():   # a frame while the node stops
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
        self.head_pub = rospy.Publisher(robot_name(HEAD_TOPIC), Float64, queue_size=1,
                                        latch=True)

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
        self.scale = 1        # frames are decoded at 1/scale (vision_scale of their width)
        self.frames = self.missed = 0       # frames seen, and gaps in their sequence
        self.last_seq = None
        self.seen, self.servo = None, None
        self.window = ImageWindow() if gui else None
        self.output_pub = rospy.Publisher(OUTPUT_TOPIC, CompressedImage, queue_size=1)
        self.decode = FrameDecoder(robot_name(CAMERA_TOPIC))
        # a few frames of slack: a burst is absorbed. Not more: rospy hands
        # over the oldest of what it kept first, and at real_time_factor 0 a
        # state machine that cannot keep up steered by frames a simulated
        # second old with 30 (it lost the ball it was playing with)
        # at real_time_factor 0 the simulator holds its frames while this node
        # is 3 frames behind (its pacing): none is lost from the queue of 3.
        # A latched empty header says so before the first frame (its first
        # frames, slow ones, were lost before it had acknowledged any)
        self.done_pub = rospy.Publisher(robot_name(FRAME_DONE_TOPIC), Header, queue_size=10,
                                        latch=True)
        self.done_pub.publish(Header())
        rospy.Subscriber(robot_name(CAMERA_TOPIC), CompressedImage, self._on_image, queue_size=3,
                         buff_size=2 ** 25)
        rospy.on_shutdown(self._report)

    def _report(self):
        if self.frames:
            rospy.loginfo('camera: %d frames, %d missed (%.2f %%)', self.frames, self.missed,
                          100.0 * self.missed / (self.frames + self.missed))

    def last_seen(self):
        return self.seen

    def follow(self, servo):
        self.servo = servo

    def _on_image(self, msg):
        try:
            self._see(msg)
        finally:
            try:
                self.done_pub.publish(Header(seq=msg.header.seq, stamp=msg.header.stamp,
                                             frame_id=msg.header.frame_id))
            except rospy.ROSException:
                if not rospy.core.is_shutdown_requested():   # a frame while the node stops
                    raise

    def _see(self, msg):
        seq = msg.header.seq
        if self.last_seq is not None and self.last_seq < seq:
            self.missed += seq - self.last_seq - 1
        self.last_seq, self.frames = seq, self.frames + 1
        scale = self.scale
        bgr = self.decode(msg, scale)
        if bgr is None:
            return
        width = bgr.shape[1] * scale
        if vision_scale(width) != scale:      # the first frame, or a new camera size
            self.scale = vision_scale(width)
        ball = self.detector.detect(bgr, scale)
        if ball is not None:
            self.seen = self.clock.from_source(msg.header.stamp.to_sec())
        servo = self.servo
        if servo is not None:
            servo(ball, width)
        self.clock.notify()
        wanted = self.output_pub.get_num_connections() > 0
        if wanted or self.window is not None:
            if scale != 1:                     # the view is drawn at full size
                bgr = self.decode(msg)
            annotate(bgr, ball)
            if self.window is not None:
                self.window.show(bgr)
            if wanted:
                self.output_pub.publish(CompressedImage(
                    header=msg.header, format='bgr8; jpeg compressed bgr8',
                    data=encode_jpeg(bgr)))

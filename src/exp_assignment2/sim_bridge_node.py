"""The ROS side of the simulator: what gazebo_ros published for the originals.

Runs :class:`~exp_assignment2.simulator.Simulator` in the node's main thread
(pybullet is single-threaded) and publishes ``/clock``, odometry + TF, joint
states and a compressed camera image with its ``camera_info``. Subscriber
callbacks only queue commands; the loop applies them between steps. JPEG
encoding runs on a second thread so it overlaps the next physics steps.

Topics per model (``ns`` is the model's namespace): ``ns/cmd_vel``,
``ns/odom``; diff-drive robots also ``ns/joint_states``,
``ns/joint_position_controller/command`` and, with a ``camera_link``,
``ns/camera1/image_raw/compressed`` and ``ns/camera1/camera_info``;
kinematic bodies (the ball) the service ``ns/set_visible``. The node's own
services ``~pause_physics``, ``~unpause_physics`` and ``~reset_world``
(std_srvs/Empty) are Gazebo's when the node is named ``gazebo``.
"""
import collections
import math
import os
import queue
import threading
import time

import cv2
import rospkg
import rospy
from geometry_msgs.msg import TransformStamped, Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import CameraInfo, CompressedImage, JointState
from std_msgs.msg import Float64
from std_srvs.srv import Empty, EmptyResponse, SetBool, SetBoolResponse
from tf2_msgs.msg import TFMessage

from exp_assignment2.simulator import Simulator
from exp_assignment2.world import parse_models

JPEG_FORMAT = 'rgb8; jpeg compressed bgr8'   # what image_transport writes


def camera_info(width, height, hfov_rad, frame_id):
    """A plumb_bob CameraInfo for an ideal pinhole with horizontal fov ``hfov_rad``."""
    f = width / (2.0 * math.tan(hfov_rad / 2.0))
    cx, cy = width / 2.0, height / 2.0
    info = CameraInfo()
    info.header.frame_id = frame_id
    info.width, info.height = width, height
    info.distortion_model = 'plumb_bob'
    info.D = [0.0] * 5
    info.K = [f, 0, cx, 0, f, cy, 0, 0, 1]
    info.R = [1, 0, 0, 0, 1, 0, 0, 0, 1]
    info.P = [f, 0, cx, 0, 0, f, cy, 0, 0, 0, 1, 0]
    return info


def encode_frame(rgba, params):
    """JPEG bytes of a rendered RGBA frame: the bridge's work per frame after
    rendering (one colour conversion, one encode)."""
    bgr = cv2.cvtColor(rgba, cv2.COLOR_RGBA2BGR)
    ok, jpeg = cv2.imencode('.jpg', bgr, params)
    if not ok:
        raise ValueError('JPEG encoding failed')
    return jpeg.tobytes()


def jpeg_params(quality):
    return [int(cv2.IMWRITE_JPEG_QUALITY), int(quality)]


class Camera(object):
    """A robot camera: renders on demand and encodes on a worker thread."""

    def __init__(self, sim, model, width, height, hfov_deg, rate, quality):
        self.sim, self.model = sim, model
        self.width, self.height, self.hfov_deg = width, height, hfov_deg
        self.period = 1.0 / rate
        self.quality = int(quality)
        self.next_time = 0.0
        self.image_pub = rospy.Publisher(model.topic('camera1/image_raw/compressed'),
                                         CompressedImage, queue_size=1)
        self.info_pub = rospy.Publisher(model.topic('camera1/camera_info'),
                                        CameraInfo, queue_size=1)
        self.info = camera_info(width, height, math.radians(hfov_deg), 'camera_link')
        self.frames = queue.Queue(maxsize=2)
        self.worker = threading.Thread(target=self._encode_loop, daemon=True)
        self.worker.start()

    def wanted(self):
        """Someone listens: nothing is rendered or encoded for no one."""
        return self.image_pub.get_num_connections() > 0

    def maybe_render(self, sim_time, stamp):
        if sim_time + 1e-9 < self.next_time:
            return
        if self.next_time < sim_time - self.period:
            self.next_time = sim_time      # after a pause or a lull, do not burst
        self.next_time += self.period
        if self.wanted():
            rgba = self.sim.render(self.model.name, 'camera_link', self.width,
                                   self.height, self.hfov_deg)
            self.frames.put((stamp, rgba))   # blocks if the encoder is 2 behind
        elif self.info_pub.get_num_connections() > 0:
            self._publish_info(stamp)

    def _publish_info(self, stamp):
        self.info.header.stamp = stamp
        self.info_pub.publish(self.info)

    def _encode_loop(self):
        params = jpeg_params(self.quality)
        while True:
            stamp, rgba = self.frames.get()
            if stamp is None:
                return
            try:
                data = encode_frame(rgba, params)
            except ValueError as exc:
                rospy.logerr_throttle(10, 'camera: %s' % exc)
                continue
            msg = CompressedImage()
            msg.header.stamp = stamp
            msg.header.frame_id = 'camera_link'
            msg.format = JPEG_FORMAT
            msg.data = data
            self.image_pub.publish(msg)
            self._publish_info(stamp)

    def close(self):
        self.frames.put((None, None))


class SimBridge(object):
    """Owns the simulator, the publishers and the stepping loop."""

    def __init__(self):
        urdf_dir = rospy.get_param('~urdf_dir', os.path.join(
            rospkg.RosPack().get_path('exp_assignment2'), 'urdf'))
        self.models = parse_models(rospy.get_param('~models'))
        self.rtf = float(rospy.get_param('~real_time_factor', 1.0))
        if not math.isfinite(self.rtf) or self.rtf < 0:
            raise ValueError('~real_time_factor must be >= 0 (0: as fast as possible)')
        odom_rate = float(rospy.get_param('~odom_rate', 50.0))
        self.sim = Simulator(self.models, urdf_dir,
                             time_step=float(rospy.get_param('~time_step', 0.01)),
                             renderer=rospy.get_param('~renderer', 'auto'),
                             cmd_timeout=float(rospy.get_param('~cmd_timeout', 0.5)))
        rospy.loginfo('simulator: renderer %s, step %.4f s, real_time_factor %g',
                      self.sim.renderer_name, self.sim.time_step, self.rtf)
        self.step_ns = int(round(self.sim.time_step * 1e9))
        self.odom_period = 1.0 / odom_rate
        self.next_odom = 0.0
        self.pending = collections.deque()     # commands from callbacks, run in the loop
        self.paused = bool(rospy.get_param('~paused', False))   # Gazebo's paused:=true
        self.stop = threading.Event()
        self.clock_pub = rospy.Publisher('/clock', Clock, queue_size=10)
        self.tf_pub = rospy.Publisher('/tf', TFMessage, queue_size=10)
        self.odom_pubs, self.joint_pubs, self.cameras = {}, {}, []
        for model in self.models:
            self._wire(model, rospy.get_param)
        rospy.Service('~pause_physics', Empty, self._on_pause)
        rospy.Service('~unpause_physics', Empty, self._on_unpause)
        rospy.Service('~reset_world', Empty, self._on_reset)

    def _wire(self, model, param):
        if model.kind == 'static':
            return
        name = model.name
        self.odom_pubs[name] = rospy.Publisher(model.topic('odom'), Odometry, queue_size=10)
        rospy.Subscriber(model.topic('cmd_vel'), Twist, self._on_cmd_vel, name, queue_size=1)
        if model.kind == 'kinematic':
            rospy.Service(model.topic('set_visible'), SetBool,
                          lambda req, n=name: self._on_set_visible(n, req))
        if model.kind == 'diff_drive':
            self.joint_pubs[name] = rospy.Publisher(model.topic('joint_states'), JointState,
                                                    queue_size=10)
            if 'head_joint' in self.sim.bodies[name].joints:
                rospy.Subscriber(model.topic('joint_position_controller/command'), Float64,
                                 self._on_head, name, queue_size=1)
            if 'camera_link' in self.sim.bodies[name].links:
                size = int(param('~camera_width', 200)), int(param('~camera_height', 200))
                self.cameras.append(Camera(
                    self.sim, model, size[0], size[1],
                    float(param('~camera_hfov', 80.0)), float(param('~camera_rate', 30.0)),
                    int(param('~jpeg_quality', 80))))

    # callbacks: validate, then queue for the loop
    def _on_cmd_vel(self, msg, name):
        values = (msg.linear.x, msg.linear.y, msg.angular.z)
        if not all(math.isfinite(v) for v in values):
            rospy.logwarn_throttle(5, '%s: ignoring a non-finite velocity command %s'
                                   % (name, values))
            return
        self.pending.append(lambda: self.sim.set_velocity(name, *values))

    def _on_head(self, msg, name):
        if not math.isfinite(msg.data):
            rospy.logwarn_throttle(5, '%s: ignoring a non-finite head command %r'
                                   % (name, msg.data))
            return
        self.pending.append(lambda: self.sim.set_head(name, msg.data))

    def _run_in_loop(self, fn, timeout=5.0):
        """Run ``fn`` in the simulator thread and wait (with a timeout) for it."""
        done = threading.Event()

        def call():
            fn()
            done.set()
        self.pending.append(call)
        return done.wait(timeout)

    def _on_set_visible(self, name, req):
        ok = self._run_in_loop(lambda: self.sim.set_visible(name, req.data))
        return SetBoolResponse(ok, '%s %s' % (name, 'shown' if req.data else 'hidden'))

    def _on_pause(self, _req):
        self.paused = True
        return EmptyResponse()

    def _on_unpause(self, _req):
        self.paused = False
        return EmptyResponse()

    def _on_reset(self, _req):
        self._run_in_loop(self.sim.reset)
        return EmptyResponse()

    # the loop
    def wait_for_camera_subscriber(self, timeout):
        """Hold the world still until a camera has a subscriber (or ``timeout``
        wall s): at real_time_factor 0 it would otherwise run ahead of nodes
        that are still starting."""
        end = time.monotonic() + timeout
        while (self.cameras and not any(c.wanted() for c in self.cameras)
               and time.monotonic() < end and not rospy.is_shutdown()):
            self._publish_clock()
            self.stop.wait(0.05)
        if self.cameras and not any(c.wanted() for c in self.cameras):
            rospy.logwarn('simulator: no camera subscriber after %.0f s; starting anyway', timeout)

    def spin(self):
        self._publish_clock()
        if rospy.get_param('~wait_for_camera', False):
            self.wait_for_camera_subscriber(float(rospy.get_param('~start_timeout', 30.0)))
        wall0, sim0 = time.monotonic(), self.sim.time
        while not rospy.is_shutdown() and not self.stop.is_set():
            while self.pending:
                self.pending.popleft()()
            if self.paused:         # the clock stands still but is still published
                self._publish_clock()
                self.stop.wait(0.05)
                wall0, sim0 = time.monotonic(), self.sim.time
                continue
            self.sim.step()
            stamp = self._publish_clock()
            if self.sim.time + 1e-9 >= self.next_odom:
                self.next_odom += self.odom_period
                self._publish_state(stamp)
            for camera in self.cameras:
                camera.maybe_render(self.sim.time, stamp)
            if self.rtf > 0:
                ahead = (sim0 + (time.monotonic() - wall0) * self.rtf)
                delay = (self.sim.time - ahead) / self.rtf
                if delay > 0:
                    self.stop.wait(delay)
                elif delay < -0.25:   # fell behind (a slow frame): do not race to catch up
                    wall0, sim0 = time.monotonic(), self.sim.time
        for camera in self.cameras:
            camera.close()
        self.sim.close()

    def _publish_clock(self):
        stamp = rospy.Time(0, self.sim.steps * self.step_ns)
        self.clock_pub.publish(Clock(clock=stamp))
        return stamp

    def _publish_state(self, stamp):
        transforms = []
        for model in self.models:
            if model.kind == 'static':
                continue
            (pos, quat) = self.sim.pose(model.name)
            (lin, ang) = self.sim.twist(model.name)
            odom = Odometry()
            odom.header.stamp = stamp
            odom.header.frame_id = 'odom'
            odom.child_frame_id = model.base_frame
            pose = odom.pose.pose
            pose.position.x, pose.position.y, pose.position.z = pos
            (pose.orientation.x, pose.orientation.y,
             pose.orientation.z, pose.orientation.w) = quat
            tw = odom.twist.twist
            tw.linear.x, tw.linear.y, tw.linear.z = lin
            tw.angular.x, tw.angular.y, tw.angular.z = ang
            self.odom_pubs[model.name].publish(odom)
            tf = TransformStamped()
            tf.header = odom.header
            tf.child_frame_id = model.base_frame
            tf.transform.translation.x, tf.transform.translation.y, \
                tf.transform.translation.z = pos
            tf.transform.rotation = pose.orientation
            transforms.append(tf)
            if model.name in self.joint_pubs:
                names, positions, velocities, efforts = self.sim.joint_states(model.name)
                self.joint_pubs[model.name].publish(JointState(
                    header=odom.header.__class__(stamp=stamp), name=names,
                    position=positions, velocity=velocities, effort=efforts))
        if transforms:
            self.tf_pub.publish(TFMessage(transforms=transforms))


def main():
    rospy.init_node('gazebo')
    try:
        bridge = SimBridge()
    except (ValueError, KeyError, RuntimeError) as exc:
        rospy.logfatal('simulator: %s', exc)
        raise SystemExit(1)
    rospy.on_shutdown(bridge.stop.set)
    bridge.spin()

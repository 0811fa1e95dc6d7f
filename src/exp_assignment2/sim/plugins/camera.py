"""A robot camera as Gazebo's camera plugin published it: a JPEG stream on
``<ns>/<name>/image_raw/compressed`` (what image_transport's compressed
publisher sends) and ``<ns>/<name>/camera_info``.

Frames are due at ``rate`` Hz of simulated time. The simulator's thread
captures a frame (pybullet calls) and hands it to one worker thread that
renders (``gl``), converts and encodes it, so that work overlaps the next
physics steps. The hand-over holds one frame: when the worker is behind, the
simulator waits rather than drop or queue frames, so the rate in simulated
time stays exact. Nothing is rendered or encoded while nobody subscribes.
"""
import copy
import queue
import threading

import rospy
from sensor_msgs.msg import CameraInfo, CompressedImage
from std_msgs.msg import Header

from exp_assignment2.sim.camera import CameraSpec, PybulletRenderer, make_renderer
from exp_assignment2.vision import encode_jpeg

JPEG_FORMAT = 'rgb8; jpeg compressed bgr8'   # what image_transport writes for rgb8 images


class FrameWorker(object):
    """The thread that finishes frames; owns the renderer's GL context."""

    def __init__(self, kind, physics):
        self.backend = make_renderer(kind, physics)
        self.jobs = queue.Queue(maxsize=1)
        self.started = threading.Event()
        self.error = None
        self.thread = threading.Thread(target=self._run, name='camera', daemon=True)
        self.thread.start()
        self.started.wait()
        if self.error is not None:
            rospy.logwarn('camera: renderer %s cannot start (%s); using tiny instead'
                          % (kind, self.error))
            self.backend = PybulletRenderer(physics, 'tiny')
            self.thread = threading.Thread(target=self._loop, name='camera', daemon=True)
            self.thread.start()
        rospy.loginfo('camera: renderer %s', self.backend.name)

    def _run(self):
        try:
            self.backend.start()        # a GL context belongs to this thread
        except RuntimeError as exc:
            self.error = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
            self.started.set()
            return
        self.started.set()
        self._loop()

    def _loop(self):
        while True:
            item = self.jobs.get()
            if item is None:
                break
            camera, stamp, job = item
            try:
                camera.publish(stamp, self.backend.finish(job))
            except Exception as exc:     # a bad frame must not stop the camera
                rospy.logerr_throttle(10.0, 'camera: frame dropped: %s' % exc)
        self.backend.close()

    def submit(self, camera, stamp, job):
        self.jobs.put((camera, stamp, job))     # waits while the worker is busy

    def close(self):
        self.jobs.put(None)
        self.thread.join(5.0)


class CameraPlugin(object):
    """One camera; ``width``, ``height``, ``rate``, ``hfov`` can be overridden
    by the simulator node's ``~camera_*`` parameters."""

    def __init__(self, sim, model, options):
        options = dict(options, **sim.camera_overrides)
        self.sim, self.spec = sim, CameraSpec(model.name, options)
        if sim.frame_worker is None:
            sim.frame_worker = FrameWorker(sim.renderer_kind, sim.physics)
        self.worker = sim.frame_worker
        base = model.topic(self.spec.name)
        self.image_pub = rospy.Publisher(base + '/image_raw/compressed', CompressedImage,
                                         queue_size=1)
        self.info_pub = rospy.Publisher(base + '/camera_info', CameraInfo, queue_size=1)
        self.info = CameraInfo(width=self.spec.width, height=self.spec.height,
                               distortion_model='plumb_bob', D=[0.0] * 5,
                               R=[1, 0, 0, 0, 1, 0, 0, 0, 1])
        self.info.K, self.info.P = self.spec.intrinsics()
        self.period, self.next = 1.0 / self.spec.rate, 0.0

    def wanted(self):
        """Someone subscribes to the image."""
        return self.image_pub.get_num_connections() > 0

    def after_step(self, stamp):
        if self.sim.physics.time + 1e-9 < self.next:
            return
        self.next += self.period
        if self.wanted():
            self.worker.submit(self, stamp, self.worker.backend.capture(self.spec))
        elif self.info_pub.get_num_connections() > 0:
            self._publish_info(stamp)

    def publish(self, stamp, bgr):
        """Encode and publish a finished frame (worker thread)."""
        msg = CompressedImage(format=JPEG_FORMAT,
                              data=encode_jpeg(bgr, self.spec.jpeg_quality))
        msg.header.stamp, msg.header.frame_id = stamp, self.spec.link
        self.image_pub.publish(msg)
        self._publish_info(stamp)

    def _publish_info(self, stamp):
        info = copy.copy(self.info)     # two threads publish it: no shared header
        info.header = Header(stamp=stamp, frame_id=self.spec.link)
        self.info_pub.publish(info)

    def reset(self):
        self.next = self.sim.physics.time

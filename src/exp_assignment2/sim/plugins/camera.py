"""``libgazebo_ros_camera.so`` inside a ``<sensor type="camera">``: what
Gazebo's camera plugin publishes through image_transport.

* ``<ns>/<cameraName>/<imageTopicName>/compressed``: JPEG frames, ``format``
  as image_transport's compressed publisher writes it;
* ``<ns>/<cameraName>/<imageTopicName>``: sensor_msgs/Image in the sensor's
  format (``R8G8B8``: rgb8), same stamp and frame as the JPEG;
* ``<ns>/<cameraName>/<cameraInfoTopicName>``.

At real_time_factor 0 (the host's ``frame_pace`` setting) the camera also
listens on ``<ns>/<cameraName>/frame_done`` (std_msgs/Header: the header of a
frame a consumer has finished with, as the state machine sends, latching an
empty one at its start) and holds the simulation while such a consumer is
:data:`PACE_WINDOW` frames behind (:class:`~exp_assignment2.sim.pacing.FramePace`):
as fast as possible is then as fast as the dog's vision, and it loses no frame.

Each is made only while it has a subscriber (rospy tells the plugin when
subscribers come and go), so an unwatched camera costs nothing. Frames are
due at the sensor's update_rate in simulated time. The simulator's thread
captures a frame (pybullet calls) and hands it to one worker thread, shared
by every camera, that renders (``gl``), converts and encodes it, so that work
overlaps the next physics steps. The hand-over holds one frame: when the
worker is behind, the simulator waits rather than drop or queue frames, so
the rate in simulated time stays exact. A frame whose scene did not move
since the camera last drew (robot, head and ball still: ``gl``'s capture
compares every link's pose) is not drawn or encoded again: the last frame's
JPEG and raw bytes are published again with the new stamp.
"""
import copy
import math

import cv2
from sensor_msgs.msg import CameraInfo, CompressedImage, Image
from std_msgs.msg import Header

from exp_assignment2.sim.camera import CameraSpec
from exp_assignment2.sim.pacing import FramePace
from exp_assignment2.sim.plugins.base import Plugin, PluginError
from exp_assignment2.sim.plugins.frame_worker import shared_worker
from exp_assignment2.sim.plugins.cores import Every
from exp_assignment2.sim.plugins.ros_io import Watched, stamp, subscribe
from exp_assignment2.vision import encode_jpeg

JPEG_FORMAT = 'rgb8; jpeg compressed bgr8'   # what image_transport writes for rgb8 images
DEFAULT_RATE = 30.0   # a sensor with update_rate 0 (as fast as Gazebo renders)


def sensor_spec(plugin, settings):
    """The :class:`~exp_assignment2.sim.camera.CameraSpec` of the plugin's
    sensor, the host's ``camera`` settings (width, height, rate, hfov in
    degrees) overriding what the URDF says."""
    sensor = plugin.sensor
    if sensor is None or sensor.type != 'camera':
        raise PluginError('%s: must sit in a <sensor type="camera">' % plugin.options.where,
                          None if sensor is not None else  # Gazebo's, for a model plugin
                          'Model[%s] is attempting to load a plugin, but detected an incorrect '
                          'plugin type. Plugin filename[%s] name[%s]'
                          % (plugin.model.name, plugin.filename, plugin.name))
    cam = sensor.options.get('camera', {})
    cam = cam if isinstance(cam, dict) else {}
    image, clip = cam.get('image') or {}, cam.get('clip') or {}
    values = dict(width=image.get('width', 320), height=image.get('height', 240),
                  hfov=math.degrees(float(cam.get('horizontal_fov', 1.047))),
                  near=clip.get('near', 0.1), far=clip.get('far', 100.0),
                  rate=sensor.update_rate or plugin.options.number('updateRate', 0.0)
                  or DEFAULT_RATE)
    values.update({k: v for k, v in settings.items() if v is not None})
    try:
        return CameraSpec(plugin.model.name, sensor.link,
                          name=plugin.options.text('cameraName', sensor.name or 'camera'),
                          width=int(float(values['width'])), height=int(float(values['height'])),
                          rate=float(values['rate']), hfov=float(values['hfov']),
                          near=float(values['near']), far=float(values['far']),
                          image_format=image.get('format', 'R8G8B8') or 'R8G8B8',
                          jpeg_quality=int(settings.get('jpeg_quality') or 80),
                          offset=sensor.pose)
    except (TypeError, ValueError) as exc:
        raise PluginError('%s: %s' % (plugin.options.where, exc))


IMAGE_QUEUE = 4
# frames a pacing consumer may have unacknowledged: rospy reads what has come
# while a callback ran and keeps the newest queue_size of it, so a window as
# long as the state machine's queue (3) loses none
PACE_WINDOW = 3


class CameraPlugin(Plugin):
    """One camera (see the module docstring): cameraName, imageTopicName,
    cameraInfoTopicName, frameName, updateRate."""

    FILENAMES = ('libgazebo_ros_camera.so',)

    def load(self):
        settings = dict(self.engine.settings.get('camera') or {})
        self.spec = spec = sensor_spec(self, settings)
        # Kinetic and Melodic prefix it with the robot namespace (releases.py)
        self.frame_id = self.engine.release.frame(self.options.text('frameName', spec.link),
                                                  self.namespace)
        base = self.topic(spec.name)
        image = self.options.text('imageTopicName', 'image_raw')
        self.on_subscribed = None      # called when someone starts watching a stream
        # frames kept for a subscriber that is a moment late (Gazebo's keep 2;
        # at real_time_factor 0 a frame leaves every 7 ms of wall time, from
        # their own thread, and every one should arrive)
        self.jpeg = Watched(base + '/' + image + '/compressed', CompressedImage, self._watch,
                            queue_size=IMAGE_QUEUE)
        self.raw = Watched(base + '/' + image, Image, self._watch, queue_size=IMAGE_QUEUE)
        self.info_pub = Watched(base + '/' + self.options.text('cameraInfoTopicName',
                                                               'camera_info'), CameraInfo,
                                queue_size=IMAGE_QUEUE)
        self.info = CameraInfo(width=spec.width, height=spec.height,
                               distortion_model='plumb_bob', D=[0.0] * 5,
                               R=[1, 0, 0, 0, 1, 0, 0, 0, 1])
        self.info.K, self.info.P = spec.intrinsics()
        self.every = Every(spec.rate, lambda: self.engine.time)
        self.pace, self.done_sub = None, None
        if self.engine.settings.get('frame_pace'):
            self.pace = FramePace(PACE_WINDOW, log=self.engine.log)
            self.done_sub = subscribe(base + '/frame_done', Header, self._on_done, queue_size=10)
        self.sent = {}      # publishing thread: this frame's JPEG and raw Image
        self.frames = [0, 0]    # frames drawn, frames of a still scene sent again
        self.worker = shared_worker(self.engine)

    def facts(self):
        """Its sensor, with the name its frames carry (``<model>/<cameraName>``), its
        compressed topic, and its horizontal field of view (rad) and width (px): what
        the grader tells the ball in view by."""
        return dict(Plugin.facts(self), camera=self.spec.name, image=self.jpeg.pub.resolved_name,
                    hfov=round(math.radians(self.spec.hfov), 4), width=self.spec.width)

    def _watch(self):
        if self.on_subscribed is not None and self.wanted():
            self.on_subscribed()

    def _on_done(self, header):
        consumer = (getattr(header, '_connection_header', None) or {}).get('callerid', '?')
        self.pace.done(consumer, header.stamp.to_nsec())

    def wanted(self):
        """Someone subscribes to an image stream."""
        return self.jpeg.wanted or self.raw.wanted

    def after_step(self):
        if not self.every.due():
            return
        when = stamp(self.engine)
        if self.wanted():
            if self.pace is not None:
                self.pace.wait()
            self.worker.submit(self, when, self.worker.backend.capture(self.spec))
            if self.pace is not None:
                self.pace.sent_frame(when.to_nsec())
        elif self.info_pub.wanted:
            self._publish_info(when)

    def publish(self, when, bgr, same=False):
        """Encode and publish a finished frame (worker thread). ``same``: its
        scene is the last frame's, whose JPEG and raw bytes go out again with
        this stamp (the same bytes the encoder would make of the same pixels)."""
        header = Header(stamp=when, frame_id=self.frame_id)
        self.frames[same] += 1
        if not same:
            self.sent = {}      # the bytes made of this frame, per stream
        if self.jpeg.wanted:
            if 'jpeg' not in self.sent:
                self.sent['jpeg'] = encode_jpeg(bgr, self.spec.jpeg_quality)
            self.jpeg.pub.publish(CompressedImage(header=header, format=JPEG_FORMAT,
                                                  data=self.sent['jpeg']))
        if self.raw.wanted:
            if 'raw' not in self.sent:
                self.sent['raw'] = raw_image(header, bgr, self.spec.encoding)
            image = copy.copy(self.sent['raw'])
            image.header = header
            self.raw.pub.publish(image)
        self._publish_info(when)
        self.engine.frame_drawn('%s/%s' % (self.model.name, self.spec.name), when.to_sec(), bgr)

    def _publish_info(self, when):
        info = copy.copy(self.info)     # two threads publish it: no shared header
        info.header = Header(stamp=when, frame_id=self.frame_id)
        self.info_pub.pub.publish(info)

    def reset(self):
        self.every.reset()
        if self.pace is not None:
            self.pace.reset()

    def close(self):
        if self.done_sub is not None:
            self.done_sub.unregister()
        self.worker.drain()
        if sum(self.frames):
            self.engine.log.info('camera %s: %d frames, %d of them of a still scene (not drawn '
                                 'again), %d x %d' % (self.spec.name, sum(self.frames),
                                                      self.frames[1], self.spec.width,
                                                      self.spec.height))
        for watched in (self.jpeg, self.raw, self.info_pub):
            watched.pub.unregister()


def raw_image(header, bgr, encoding):
    """A sensor_msgs/Image of a BGR frame in ``encoding`` (rgb8, bgr8, mono8)."""
    if encoding == 'rgb8':
        pixels = cv2.cvtColor(bgr, cv2.COLOR_BGR2RGB)
    elif encoding == 'mono8':
        pixels = cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY)
    else:
        pixels = bgr
    height, width = pixels.shape[:2]
    channels = 1 if pixels.ndim == 2 else pixels.shape[2]
    return Image(header=header, height=height, width=width, encoding=encoding, is_bigendian=0,
                 step=width * channels, data=pixels.tobytes())

"""The robot camera without ROS: intrinsics, pose and the renderers.

:class:`CameraSpec` is a ``<sensor type="camera">`` as Gazebo reads it
(update_rate, horizontal_fov, image width, height and format, clip), on its
link, looking along the sensor frame's +x with +z up.

A renderer backend splits a frame in two halves so that rendering can
overlap physics: :meth:`capture` runs in the simulator's thread (the only
one allowed to call pybullet) and returns a job; :meth:`finish` runs on the
camera's worker thread and returns the BGR image. Backends draw the world a
``source`` gives: ``source.scene()`` -> (generation, models), the
generation changing whenever a model is spawned or deleted.

* ``gl`` (default): the package's own OpenGL renderer (moderngl, EGL);
  capture reads every link pose in one batched query, finish draws.
* ``egl`` and ``tiny``: pybullet's renderers; capture renders (pybullet is
  single-threaded), finish only converts the colours.
"""
import math

import cv2
import numpy as np
from exp_assignment2.sim.bullet import p

from exp_assignment2.sim.rotations import pose_matrix, rpy_matrix

# Gazebo image formats -> (ROS encoding, channels)
IMAGE_FORMATS = {'R8G8B8': 'rgb8', 'B8G8R8': 'bgr8', 'L8': 'mono8'}


class CameraSpec(object):
    """A pinhole camera (see the module docstring).

    :param offset: (x, y, z, roll, pitch, yaw) of the sensor in its link's frame
    :param world_pose: a 4x4 world pose for a camera on no link (Gazebo's user
        camera, :mod:`~exp_assignment2.sim.user_camera`); model and link None
    """

    def __init__(self, model, link, name='camera1', width=320, height=240, rate=30.0,
                 hfov=60.0, near=0.1, far=100.0, image_format='R8G8B8', jpeg_quality=80,
                 offset=(0, 0, 0, 0, 0, 0), world_pose=None):
        self.model, self.link, self.name = model, link, name
        self.width, self.height = int(width), int(height)
        self.rate, self.hfov = float(rate), float(hfov)
        self.near, self.far = float(near), float(far)
        self.jpeg_quality = int(jpeg_quality)
        if image_format not in IMAGE_FORMATS:
            raise ValueError('model %s: camera %s: image format %r is not one of %s'
                             % (model, name, image_format, ', '.join(sorted(IMAGE_FORMATS))))
        self.encoding = IMAGE_FORMATS[image_format]
        if not (0 < self.hfov < 180 and 0 < self.near < self.far and self.rate > 0
                and self.width > 0 and self.height > 0):
            raise ValueError('model %s: camera %s %dx%d, hfov %g deg, near %g, far %g, rate %g:'
                             ' out of range' % (model, name, self.width, self.height, self.hfov,
                                                self.near, self.far, self.rate))
        self.offset = np.eye(4)
        self.offset[:3, :3] = rpy_matrix(*offset[3:])
        self.offset[:3, 3] = offset[:3]
        self.world_pose = None if world_pose is None else np.asarray(world_pose, float)

    @property
    def focal(self):
        """Focal length (px): f = width / (2 tan(hfov / 2))."""
        return self.width / (2.0 * math.tan(math.radians(self.hfov) / 2.0))

    def intrinsics(self):
        """(K, P) row-major, as sensor_msgs/CameraInfo has them."""
        f, cx, cy = self.focal, self.width / 2.0, self.height / 2.0
        return [f, 0, cx, 0, f, cy, 0, 0, 1], [f, 0, cx, 0, 0, f, cy, 0, 0, 0, 1, 0]

    def vertical_fov(self):
        """Vertical field of view (deg) that goes with hfov at this aspect."""
        aspect = float(self.width) / self.height
        return math.degrees(2.0 * math.atan(math.tan(math.radians(self.hfov) / 2.0) / aspect))

    def frame(self, link_frame):
        """4x4 world pose of the sensor, given its link's (None for a camera on no link)."""
        if self.world_pose is not None:
            return self.world_pose
        return np.asarray(link_frame, float).dot(self.offset)


class PybulletRenderer(object):
    """pybullet's TinyRenderer (CPU) or its EGL plugin."""

    def __init__(self, source, kind, client, egl_loaded=False):
        self.source, self.name, self.client = source, kind, client
        self._renderer = p.ER_TINY_RENDERER
        if kind == 'egl':
            if not egl_loaded:
                raise RuntimeError('the egl renderer needs the physics world made with '
                                   'egl=True: the plugin only draws bodies loaded after it')
            self._renderer = p.ER_BULLET_HARDWARE_OPENGL

    def start(self):
        pass

    def matrices(self, camera):
        link = None
        if camera.world_pose is None:
            models = {m.name: m for m in self.source.scene()[1]}
            link = pose_matrix(*models[camera.model].link_pose(camera.link))
        frame = camera.frame(link)
        pos, rot = frame[:3, 3], frame[:3, :3]
        view = p.computeViewMatrix(pos.tolist(), (pos + rot[:, 0]).tolist(), rot[:, 2].tolist())
        proj = p.computeProjectionMatrixFOV(camera.vertical_fov(),
                                            float(camera.width) / camera.height,
                                            camera.near, camera.far)
        return view, proj

    def render_raw(self, camera):
        """pybullet's getCameraImage alone (the benchmark's yardstick)."""
        view, proj = self.matrices(camera)
        return p.getCameraImage(camera.width, camera.height, view, proj,
                                renderer=self._renderer, flags=p.ER_NO_SEGMENTATION_MASK,
                                physicsClientId=self.client)

    def capture(self, camera):
        rgba = self.render_raw(camera)[2]
        return np.asarray(rgba, dtype=np.uint8).reshape(camera.height, camera.width, 4)

    def finish(self, job):
        return cv2.cvtColor(job, cv2.COLOR_RGBA2BGR)

    def close(self):
        pass    # the plugin, if any, belongs to the physics


RENDERERS = ('gl', 'egl', 'tiny')


def make_renderer(kind, source, client, egl_loaded=False):
    """The backend ``kind`` names; ValueError for an unknown name."""
    if kind not in RENDERERS:
        raise ValueError('renderer must be one of %s, got %r' % (', '.join(RENDERERS), kind))
    if kind == 'gl':
        from exp_assignment2.sim.gl.backend import GLBackend
        return GLBackend(source, client)
    return PybulletRenderer(source, kind, client, egl_loaded)

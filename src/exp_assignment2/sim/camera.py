"""The robot camera without ROS: intrinsics, pose and the renderers.

A renderer backend splits a frame in two halves so that rendering can
overlap physics: :meth:`capture` runs in the simulator's thread (the only
one allowed to call pybullet) and returns a job; :meth:`finish` runs on the
camera's worker thread and returns the BGR image. Backends:

* ``gl`` (default): the package's own OpenGL renderer (moderngl, EGL);
  capture reads every link pose in one batched query, finish draws.
* ``egl`` and ``tiny``: pybullet's renderers; capture renders (pybullet is
  single-threaded), finish only converts the colours.
"""
import math

import cv2
import numpy as np
from exp_assignment2.sim.bullet import p


class CameraSpec(object):
    """A pinhole camera on ``link`` looking along the link's +x, +z up."""

    def __init__(self, model, options):
        self.model, self.link, self.name = model, options['link'], options['name']
        if not self.link:
            raise ValueError('model %s: camera needs a link' % model)
        self.width, self.height = int(options['width']), int(options['height'])
        self.rate, self.hfov = float(options['rate']), float(options['hfov'])
        self.near, self.far = float(options['near']), float(options['far'])
        self.jpeg_quality = int(options['jpeg_quality'])
        if not (0 < self.hfov < 180 and 0 < self.near < self.far and self.rate > 0
                and self.width > 0 and self.height > 0):
            raise ValueError('model %s: camera %dx%d, hfov %g, near %g, far %g, rate %g: '
                             'out of range' % (model, self.width, self.height, self.hfov,
                                               self.near, self.far, self.rate))

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

    def pose(self, physics):
        """(position, 3x3 rotation) of the camera in the world."""
        pos, quat = physics.link_pose(self.model, self.link)
        return np.asarray(pos), np.array(p.getMatrixFromQuaternion(quat)).reshape(3, 3)


class PybulletRenderer(object):
    """pybullet's TinyRenderer (CPU) or its EGL plugin."""

    def __init__(self, physics, kind):
        self.physics, self.name = physics, kind
        self._renderer = p.ER_TINY_RENDERER
        if kind == 'egl':
            if physics.egl_plugin is None:
                raise RuntimeError('the egl renderer needs Physics(egl=True): the plugin '
                                   'only draws bodies loaded after it')
            self._renderer = p.ER_BULLET_HARDWARE_OPENGL

    def start(self):
        pass

    def matrices(self, camera):
        pos, rot = camera.pose(self.physics)
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
                                physicsClientId=self.physics.client)

    def capture(self, camera):
        rgba = self.render_raw(camera)[2]
        return np.asarray(rgba, dtype=np.uint8).reshape(camera.height, camera.width, 4)

    def finish(self, job):
        return cv2.cvtColor(job, cv2.COLOR_RGBA2BGR)

    def close(self):
        pass    # the plugin, if any, belongs to the physics


RENDERERS = ('gl', 'egl', 'tiny')


def make_renderer(kind, physics):
    """The backend ``kind`` names; ValueError for an unknown name."""
    if kind not in RENDERERS:
        raise ValueError('renderer must be one of %s, got %r' % (', '.join(RENDERERS), kind))
    if kind == 'gl':
        from exp_assignment2.sim.gl_backend import GLBackend
        return GLBackend(physics)
    return PybulletRenderer(physics, kind)


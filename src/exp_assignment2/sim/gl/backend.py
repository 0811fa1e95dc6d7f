"""The ``gl`` renderer backend: the package's OpenGL renderer behind the
camera's capture/finish split (see :mod:`exp_assignment2.sim.camera`).

capture (simulator thread): every link pose in one batched query, which
models are hidden, and the scene description (rebuilt when models were
spawned or deleted). finish (camera worker thread, which owns the GL
context): draw and read back BGR.

A still scene is not drawn again: when no link of any model moved by more
than :data:`STILL` (metres, and rotation-matrix entries) since the last
frame a camera drew, with the same models shown, capture hands over a
:class:`Still` job and finish returns that camera's last image, whose bytes
the camera then publishes again (plugins/camera.py). STILL is far below a
pixel: 1e-6 m seen from the near clip (0.1 m) of an 800 px camera is 0.007 px.
"""
import numpy as np

from exp_assignment2.sim.gl.scene import GLRenderer, SceneReader, empty_description

PROBE_SIZE = 16
# a frame is drawn while the one before waits for the encoder, which has the
# one before that (plugins/frame_worker.py)
BUFFERS = 3
STILL = 1e-6


class Still(object):
    """A frame whose scene is the one ``camera`` last drew: nothing to draw."""

    same = True

    def __init__(self, camera):
        self.camera = camera


class GLBackend(object):
    """Draws the world's URDF visuals at the poses pybullet has for the step."""

    name = 'gl'

    def __init__(self, source, client):
        self.source, self.client = source, client
        self.generation, self.reader = None, None
        self.renderers = {}      # (width, height) -> GLRenderer, worker thread only
        self.buffers = {}        # camera -> the images finish() returns, in turn
        self.drawn = {}          # camera -> (poses, hidden, description) last drawn (sim thread)

    def start(self):
        """Open a GL context in this (the worker's) thread; RuntimeError when
        moderngl or EGL is unavailable."""
        self._renderer(PROBE_SIZE, PROBE_SIZE, empty_description())

    def _scene(self):
        generation, models = self.source.scene()
        if generation != self.generation:
            self.reader = SceneReader(models, self.client)
            self.generation = generation
        return models

    def _renderer(self, width, height, description):
        renderer = self.renderers.get((width, height))
        if renderer is None:
            renderer = GLRenderer(description, width, height)
            self.renderers[(width, height)] = renderer
        elif renderer.description is not description:
            renderer.set_scene(description)
        return renderer

    def capture(self, camera):
        """The job for ``camera``'s next frame: what to draw, or :class:`Still`."""
        models = self._scene()
        hidden = [m.name for m in models if m.hidden]
        poses, description = self.reader.read_poses(), self.reader.description
        last = self.drawn.get(camera)
        if last is not None and last[1] == hidden and last[2] is description and \
                last[0].shape == poses.shape and \
                (not len(poses) or float(np.abs(last[0] - poses).max()) <= STILL):
            return Still(camera)
        self.drawn[camera] = (poses, hidden, description)
        return camera, poses, hidden, description

    def forget(self, camera):
        """Draw ``camera``'s next frame whatever it shows (it was not published)."""
        self.drawn.pop(camera, None)

    def finish(self, job):
        """The BGR image; valid until the camera's BUFFERS-th drawn frame after
        it (its buffers rotate: one drawn, one waiting, one being encoded). A
        :class:`Still` job: the camera's last image, not drawn again."""
        if isinstance(job, Still):
            if job.camera not in self.buffers:
                raise ValueError('a still frame of a camera that drew none')
            return self.buffers[job.camera][-1]
        camera, poses, hidden, description = job
        link = None if camera.world_pose is not None else \
            description.link_pose(poses, camera.model, camera.link)
        return self._renderer(camera.width, camera.height, description).render(
            poses, camera.frame(link), hfov_deg=camera.hfov, near=camera.near, far=camera.far,
            hidden=hidden, out=self._buffer(camera), gui=camera.world_pose is not None)

    def _buffer(self, camera):
        ring = self.buffers.get(camera)
        if ring is None:
            ring = self.buffers[camera] = [np.empty((camera.height, camera.width, 3), np.uint8)
                                           for _ in range(BUFFERS)]
        ring.append(ring.pop(0))
        return ring[-1]

    def close(self):
        for renderer in self.renderers.values():
            renderer.close()
        self.renderers.clear()

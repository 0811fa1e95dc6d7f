"""The ``gl`` renderer backend: the package's OpenGL renderer behind the
camera's capture/finish split (see :mod:`exp_assignment2.sim.camera`).

capture (simulator thread): every link pose in one batched query, which
models are hidden, and the scene description (rebuilt when models were
spawned or deleted). finish (camera worker thread, which owns the GL
context): draw and read back BGR.
"""
import numpy as np

from exp_assignment2.sim.gl.scene import GLRenderer, SceneReader, empty_description

PROBE_SIZE = 16
# a frame is drawn while the one before waits for the encoder, which has the
# one before that (plugins/frame_worker.py)
BUFFERS = 3


class GLBackend(object):
    """Draws the world's URDF visuals at the poses pybullet has for the step."""

    name = 'gl'

    def __init__(self, source, client):
        self.source, self.client = source, client
        self.generation, self.reader = None, None
        self.renderers = {}      # (width, height) -> GLRenderer, worker thread only
        self.buffers = {}        # (width, height) -> the images finish() returns, in turn

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
        models = self._scene()
        hidden = [m.name for m in models if m.hidden]
        return camera, self.reader.read_poses(), hidden, self.reader.description

    def finish(self, job):
        """The BGR image; valid until the BUFFERS-th finish() after it (the
        buffers rotate: one drawn, one waiting, one being encoded)."""
        camera, poses, hidden, description = job
        pose = camera.frame(description.link_pose(poses, camera.model, camera.link))
        return self._renderer(camera.width, camera.height, description).render(
            poses, pose, hfov_deg=camera.hfov, near=camera.near, far=camera.far, hidden=hidden,
            out=self._buffer(camera.width, camera.height))

    def _buffer(self, width, height):
        ring = self.buffers.get((width, height))
        if ring is None:
            ring = self.buffers[(width, height)] = [np.empty((height, width, 3), np.uint8)
                                                    for _ in range(BUFFERS)]
        ring.append(ring.pop(0))
        return ring[-1]

    def close(self):
        for renderer in self.renderers.values():
            renderer.close()
        self.renderers.clear()

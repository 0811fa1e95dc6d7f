"""The ``gl`` renderer backend: the package's OpenGL renderer behind the
camera's capture/finish split (see :mod:`exp_assignment2.sim.camera`).

capture (simulator thread): every link pose in one batched query per body,
plus which bodies are hidden. finish (camera worker thread, which owns the
GL context): draw and read back BGR.
"""
from exp_assignment2.sim.render_gl import BulletSceneReader, GLRenderer, SceneModel

PROBE_SIZE = 16


class GLBackend(object):
    """Draws the world's URDF visuals at the poses pybullet has for the step."""

    name = 'gl'

    def __init__(self, physics):
        self.physics = physics
        models = [SceneModel(body.id, body.path, body.spec.grid, name)
                  for name, body in physics.bodies.items()]
        self.reader = BulletSceneReader(models, client=physics.client)
        self.renderers = {}      # (width, height) -> GLRenderer, worker thread only

    def start(self):
        """Open a GL context in this (the worker's) thread; RuntimeError when
        moderngl or EGL is unavailable."""
        self._renderer(PROBE_SIZE, PROBE_SIZE)

    def _renderer(self, width, height):
        renderer = self.renderers.get((width, height))
        if renderer is None:
            renderer = GLRenderer(self.reader.description, width, height)
            self.renderers[(width, height)] = renderer
        return renderer

    def capture(self, camera):
        hidden = [name for name, body in self.physics.bodies.items() if body.hidden]
        return camera, self.reader.read_poses(), hidden

    def finish(self, job):
        """The BGR image; valid until the next finish() (the buffer is reused)."""
        camera, poses, hidden = job
        pose = self.reader.description.link_pose(poses, camera.model, camera.link)
        return self._renderer(camera.width, camera.height).render(
            poses, pose, hfov_deg=camera.hfov, near=camera.near, far=camera.far, hidden=hidden)

    def close(self):
        for renderer in self.renderers.values():
            renderer.close()
        self.renderers.clear()

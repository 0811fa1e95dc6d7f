"""The pybullet world: bodies loaded and removed, stepped at a fixed step.

Plain Python (no ROS). All calls must come from one thread: pybullet clients
are not thread-safe. What a body is and does lives in
:class:`~exp_assignment2.sim.model.Model`; this module only owns the client.
"""
import math
import os
import pkgutil
import tempfile

import numpy as np
from exp_assignment2.sim.bullet import p, quiet


class BodyInfo(object):
    """What pybullet made of a URDF: its id, joints and links."""

    def __init__(self, body_id, client, root_link):
        self.id = body_id
        self.joints = {}      # name -> (index, lower, upper, child link name)
        self.links = {root_link: -1}       # link name -> index (-1: the base)
        self.movable = []     # (name, index) of the non-fixed joints, in order
        for j in range(p.getNumJoints(body_id, physicsClientId=client)):
            info = p.getJointInfo(body_id, j, physicsClientId=client)
            name, child = info[1].decode(), info[12].decode()
            self.joints[name] = (j, info[8], info[9], child)
            self.links[child] = j
            if info[2] != p.JOINT_FIXED:
                self.movable.append((name, j))
        dyn = p.getDynamicsInfo(body_id, -1, physicsClientId=client)
        self.inertial = (dyn[3], dyn[4])    # the base's centre of mass in its URDF frame


class Physics(object):
    """A pybullet DIRECT world with a fixed time step.

    :param time_step: physics step (s of simulated time)
    :param egl: load pybullet's EGL renderer plugin (it only draws bodies
        loaded after it, so it comes first)
    """

    def __init__(self, time_step=0.01, egl=False, gravity=(0.0, 0.0, -9.81)):
        if not (time_step > 0 and math.isfinite(time_step)):
            raise ValueError('time_step must be positive, got %r' % (time_step,))
        self.time_step = float(time_step)
        self.client = p.connect(p.DIRECT)
        p.setGravity(*gravity, physicsClientId=self.client)
        p.setTimeStep(self.time_step, physicsClientId=self.client)
        self._tmp = tempfile.TemporaryDirectory(prefix='exp_assignment2_')
        self._after_step = []       # once, after the next step
        self._texture = None
        self.egl_plugin = self._load_egl() if egl else None

    def load(self, name, urdf, position, quaternion, fixed):
        """Load a parsed URDF (:class:`~exp_assignment2.sim.urdf.UrdfModel`) as
        body ``name``; returns its :class:`BodyInfo`. ValueError if pybullet
        cannot load it."""
        path = os.path.join(self._tmp.name, name.replace('/', '_') + '.urdf')
        with open(path, 'w') as f:
            f.write(urdf.bullet_text())
        try:
            with quiet():
                body_id = p.loadURDF(path, list(position), list(quaternion),
                                     useFixedBase=bool(fixed), physicsClientId=self.client)
        except p.error as exc:
            raise ValueError('pybullet cannot load the URDF: %s' % exc)
        finally:
            os.remove(path)
        return BodyInfo(body_id, self.client, urdf.root)

    def remove(self, body_id):
        p.removeBody(body_id, physicsClientId=self.client)

    def step(self):
        p.stepSimulation(physicsClientId=self.client)
        while self._after_step:
            self._after_step.pop(0)()

    def after_step(self, fn):
        """Call ``fn()`` once, after the next step."""
        self._after_step.append(fn)

    def _load_egl(self):
        loader = pkgutil.get_loader('eglRenderer')
        plugin = -1
        if loader is not None:
            with quiet():
                plugin = p.loadPlugin(loader.get_filename(), '_eglRendererPlugin',
                                      physicsClientId=self.client)
        if plugin < 0:
            raise RuntimeError("pybullet's EGL renderer plugin did not load")
        return plugin

    def grid_texture(self):
        """pybullet's renderers draw the floor grid from a texture (1 m cells)."""
        if self._texture is None:
            import cv2   # only the texture needs it
            n, step = 640, 32            # 20 m at 32 px per m
            img = np.full((n, n, 3), 200, np.uint8)
            for i in range(0, n, step):
                img[i:i + 2, :] = 90
                img[:, i:i + 2] = 90
            path = os.path.join(self._tmp.name, 'grid.png')
            cv2.imwrite(path, img)
            self._texture = p.loadTexture(path, physicsClientId=self.client)
        return self._texture

    def close(self):
        if self.egl_plugin is not None:
            with quiet():
                p.unloadPlugin(self.egl_plugin, physicsClientId=self.client)
        p.disconnect(self.client)
        self._tmp.cleanup()

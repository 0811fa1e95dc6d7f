"""The pybullet world: models loaded, stepped at a fixed step, poses read.

Plain Python (no ROS). All calls must come from one thread: pybullet clients
are not thread-safe. Poses are those of the URDF frames (pybullet's base
pose is the base's centre of mass; :meth:`Physics.base_pose` corrects for it),
so what is published is what ``robot_state_publisher`` and rviz expect.
"""
import math
import os
import pkgutil
import tempfile

import numpy as np
from exp_assignment2.sim.bullet import p, quiet

from exp_assignment2.geometry import all_finite
from exp_assignment2.sim import urdf

HIDDEN_Z = -50.0   # where a hidden body is put, far below every camera's view


class Body(object):
    """A loaded model: its pybullet id, joints and links, and what drives it."""

    def __init__(self, spec, body_id, urdf_root, path):
        self.spec, self.id, self.urdf, self.path = spec, body_id, urdf_root, path
        self.joints = {}      # name -> (index, lower, upper, child link name)
        self.links = {}       # link name -> index (-1: the base)
        self.movable = []     # (name, index) of the non-fixed joints, in order
        self.inertial = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))   # base: COM in URDF frame
        self.kinematic = None  # [x, y, z, yaw] for bodies moved without physics
        self.hidden = False
        self.spawn_hidden = False


class Physics(object):
    """A pybullet DIRECT world with a fixed time step.

    :param world: :class:`~exp_assignment2.sim.world.WorldSpec`
    :param urdf_text: ``urdf_text(spec)`` gives a model's URDF text
    :param time_step: physics step (s of simulated time)
    :param egl: load pybullet's EGL renderer plugin (it only draws bodies
        loaded after it, so it comes first)
    """

    def __init__(self, world, urdf_text, time_step=0.01, egl=False):
        if not (time_step > 0 and math.isfinite(time_step)):
            raise ValueError('time_step must be positive, got %r' % (time_step,))
        self.world, self.time_step, self.steps = world, float(time_step), 0
        self.client = p.connect(p.DIRECT)
        p.setGravity(0, 0, -9.81, physicsClientId=self.client)
        p.setTimeStep(self.time_step, physicsClientId=self.client)
        self._tmp = tempfile.TemporaryDirectory(prefix='exp_assignment2_')
        self._texture = None
        self.egl_plugin = self._load_egl() if egl else None
        self.bodies = {}
        for spec in world.models:
            self.bodies[spec.name] = self._load(spec, urdf_text(spec))

    @property
    def time(self):
        """Simulated time (s) since start: steps x step, so it never drifts."""
        return self.steps * self.time_step

    def _load(self, spec, text):
        root = urdf.parse(text)
        path = os.path.join(self._tmp.name, spec.name + '.urdf')
        with open(path, 'w') as f:
            f.write(text)
        x, y, z, yaw = spec.pose
        drive = spec.plugins.get('planar_move')
        kinematic = drive is not None and drive['kinematic']
        fixed = spec.drive is None or kinematic
        body_id = p.loadURDF(path, [x, y, z], p.getQuaternionFromEuler([0, 0, yaw]),
                             useFixedBase=fixed, physicsClientId=self.client)
        body = Body(spec, body_id, root, path)
        body.links[root.find('link').get('name')] = -1
        for j in range(p.getNumJoints(body_id, physicsClientId=self.client)):
            info = p.getJointInfo(body_id, j, physicsClientId=self.client)
            name, child = info[1].decode(), info[12].decode()
            body.joints[name] = (j, info[8], info[9], child)
            body.links[child] = j
            if info[2] != p.JOINT_FIXED:
                body.movable.append((name, j))
        dyn = p.getDynamicsInfo(body_id, -1, physicsClientId=self.client)
        body.inertial = (dyn[3], dyn[4])
        if kinematic:
            body.kinematic = [x, y, z, yaw]
        if spec.grid and self.grid_texture() is not None:
            p.changeVisualShape(body_id, -1, textureUniqueId=self._texture,
                                physicsClientId=self.client)
        return body

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
        """pybullet's renderers draw the grid from a texture (1 m cells)."""
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

    # stepping and state
    def step(self):
        p.stepSimulation(physicsClientId=self.client)
        self.steps += 1

    def base_pose(self, name):
        """World pose of a body's URDF base frame: ((x, y, z), (qx, qy, qz, qw))."""
        body = self.bodies[name]
        if body.kinematic is not None:
            x, y, z, yaw = body.kinematic
            return (x, y, z), p.getQuaternionFromEuler([0, 0, yaw])
        com = p.getBasePositionAndOrientation(body.id, physicsClientId=self.client)
        inv = p.invertTransform(*body.inertial)
        return p.multiplyTransforms(com[0], com[1], inv[0], inv[1])

    def base_twist(self, name, command=(0.0, 0.0, 0.0)):
        """A body's twist in its own frame: ((vx, vy, vz), (wx, wy, wz)).
        Kinematic bodies move as commanded (``command``: body-frame vx, vy, wz)."""
        body = self.bodies[name]
        if body.kinematic is not None:
            vx, vy, wz = command
            return (vx, vy, 0.0), (0.0, 0.0, wz)
        lin, ang = p.getBaseVelocity(body.id, physicsClientId=self.client)
        _, quat = p.getBasePositionAndOrientation(body.id, physicsClientId=self.client)
        rot = np.array(p.getMatrixFromQuaternion(quat)).reshape(3, 3)
        return tuple(rot.T.dot(lin)), tuple(rot.T.dot(ang))

    def set_base_velocity(self, name, linear, angular):
        p.resetBaseVelocity(self.bodies[name].id, linear, angular, physicsClientId=self.client)

    def place_kinematic(self, name):
        """Move a kinematic body to its pose (below the floor while hidden)."""
        body = self.bodies[name]
        x, y, z, yaw = body.kinematic
        p.resetBasePositionAndOrientation(
            body.id, [x, y, HIDDEN_Z if body.hidden else z],
            p.getQuaternionFromEuler([0, 0, yaw]), physicsClientId=self.client)

    def joint_states(self, name):
        """(names, positions, velocities, efforts) of a body's movable joints."""
        body = self.bodies[name]
        idx = [j for _, j in body.movable]
        states = p.getJointStates(body.id, idx, physicsClientId=self.client) if idx else []
        return ([n for n, _ in body.movable], [s[0] for s in states], [s[1] for s in states],
                [s[3] for s in states])

    def link_pose(self, name, link):
        """World pose of a link's URDF frame."""
        body = self.bodies[name]
        index = body.links[link]
        if index < 0:
            return self.base_pose(name)
        state = p.getLinkState(body.id, index, computeForwardKinematics=True,
                               physicsClientId=self.client)
        return state[4], state[5]

    def finite(self, name):
        """True while a body's pose and velocity are finite numbers."""
        body = self.bodies[name]
        pos, quat = p.getBasePositionAndOrientation(body.id, physicsClientId=self.client)
        lin, ang = p.getBaseVelocity(body.id, physicsClientId=self.client)
        return all_finite(*pos, *quat, *lin, *ang)

    def reset_body(self, name):
        """Put one body back at its spawn pose, at rest, joints at zero."""
        body = self.bodies[name]
        x, y, z, yaw = body.spec.pose
        quat = p.getQuaternionFromEuler([0, 0, yaw])
        com = p.multiplyTransforms([x, y, z], quat, *body.inertial)
        p.resetBasePositionAndOrientation(body.id, com[0], com[1], physicsClientId=self.client)
        p.resetBaseVelocity(body.id, [0, 0, 0], [0, 0, 0], physicsClientId=self.client)
        for j, _, _, _ in body.joints.values():
            p.resetJointState(body.id, j, 0.0, 0.0, physicsClientId=self.client)
        if body.kinematic is not None:
            body.kinematic = [x, y, z, yaw]
            body.hidden = body.spawn_hidden
            self.place_kinematic(name)

    def close(self):
        if self.egl_plugin is not None:
            with quiet():
                p.unloadPlugin(self.egl_plugin, physicsClientId=self.client)
        p.disconnect(self.client)
        self._tmp.cleanup()

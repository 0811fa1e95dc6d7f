"""A headless pybullet world that does what Gazebo did for the originals.

Plain Python (no ROS): :class:`Simulator` loads models from
:class:`~exp_assignment2.world.ModelSpec` descriptions, steps physics at a
fixed step, drives diff-drive wheels, omnidirectional bases and kinematic
bodies from velocity commands, moves a head joint, and renders a camera. The
ROS bridge (:mod:`exp_assignment2.sim_bridge_node`) wraps it. All calls must
come from one thread: pybullet clients are not thread-safe.
"""
import logging
import math
import os
import pkgutil
import tempfile

import numpy as np
import pybullet as p

log = logging.getLogger(__name__)

HIDDEN_Z = -50.0   # below the floor: out of every camera's view


def yaw_of(quat):
    """Yaw (rad) of an (x, y, z, w) quaternion."""
    x, y, z, w = quat
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def grid_texture_file(size_m, cell_m=1.0, px_per_m=32):
    """Write a floor texture with a grid line every ``cell_m`` and return its path."""
    n = int(size_m * px_per_m)
    img = np.full((n, n, 3), 200, np.uint8)
    step = int(cell_m * px_per_m)
    for i in range(0, n, step):
        img[i:i + 2, :] = 90
        img[:, i:i + 2] = 90
    import cv2  # only the texture needs it; keeps the import cost off tests
    path = os.path.join(tempfile.gettempdir(), 'exp_assignment2_grid_%d.png' % n)
    cv2.imwrite(path, img)
    return path


class Body(object):
    """A loaded model and its command state."""

    def __init__(self, spec, body_id, joints):
        self.spec = spec
        self.id = body_id
        self.joints = joints           # name -> (index, lower, upper)
        self.links = {}                # link name -> index
        self.movable = []              # (name, index) of non-fixed joints, in order
        self.cmd = (0.0, 0.0, 0.0)     # vx, vy, wz (body frame for robots)
        self.cmd_time = None           # sim time of the last command
        self.head_target = 0.0
        self.visible = True
        self.kin_pose = None           # kinematic bodies: [x, y, z, yaw]


class Simulator(object):
    """A pybullet world with fixed-step physics and a robot camera.

    :param models: list of :class:`ModelSpec`
    :param urdf_dir: where relative URDF paths are looked up
    :param time_step: physics step (s of simulated time)
    :param renderer: ``auto`` (EGL if it loads, else tiny), ``egl`` or ``tiny``
    :param cmd_timeout: velocity commands older than this (s) stop the body
    """

    def __init__(self, models, urdf_dir, time_step=0.01, renderer='auto',
                 cmd_timeout=0.5):
        self.time_step = float(time_step)
        self.cmd_timeout = float(cmd_timeout)
        self.steps = 0                 # time is steps * time_step: no drift
        self.client = p.connect(p.DIRECT)
        self.renderer_name = self._setup_renderer(renderer)
        p.setGravity(0, 0, -9.81, physicsClientId=self.client)
        p.setTimeStep(self.time_step, physicsClientId=self.client)
        self.bodies = {}
        for spec in models:
            self.bodies[spec.name] = self._load(spec, urdf_dir)
        self._texture = None

    # setup
    def _setup_renderer(self, renderer):
        if renderer not in ('auto', 'egl', 'tiny'):
            raise ValueError("renderer must be 'auto', 'egl' or 'tiny', got %r" % renderer)
        self._egl_plugin = None
        if renderer in ('auto', 'egl'):
            loader = pkgutil.get_loader('eglRenderer')
            if loader is not None:
                plugin = p.loadPlugin(loader.get_filename(), '_eglRendererPlugin',
                                      physicsClientId=self.client)
                if plugin >= 0:
                    self._egl_plugin = plugin
            if self._egl_plugin is None and renderer == 'egl':
                raise RuntimeError('the EGL renderer plugin did not load')
        if self._egl_plugin is not None:
            self._renderer = p.ER_BULLET_HARDWARE_OPENGL
            return 'egl'
        self._renderer = p.ER_TINY_RENDERER
        return 'tiny'

    def _load(self, spec, urdf_dir):
        path = spec.urdf if os.path.isabs(spec.urdf) else os.path.join(urdf_dir, spec.urdf)
        if not os.path.exists(path):
            raise ValueError('model %s: no URDF at %s' % (spec.name, path))
        x, y, z, yaw = spec.pose
        fixed = spec.kind in ('static', 'kinematic')
        body_id = p.loadURDF(path, [x, y, z], p.getQuaternionFromEuler([0, 0, yaw]),
                             useFixedBase=fixed, physicsClientId=self.client)
        joints = {}
        body = Body(spec, body_id, joints)
        for j in range(p.getNumJoints(body_id, physicsClientId=self.client)):
            info = p.getJointInfo(body_id, j, physicsClientId=self.client)
            joints[info[1].decode()] = (j, info[8], info[9])
            body.links[info[12].decode()] = j
            if info[2] != p.JOINT_FIXED:
                body.movable.append((info[1].decode(), j))
        if spec.kind == 'diff_drive':
            for name, (j, _, _) in joints.items():
                if 'wheel' in name:
                    p.changeDynamics(body_id, j, lateralFriction=1.0,
                                     physicsClientId=self.client)
            if 'caster' in body.links:
                p.changeDynamics(body_id, body.links['caster'], lateralFriction=0.0,
                                 spinningFriction=0.0, rollingFriction=0.0,
                                 physicsClientId=self.client)
        if spec.kind == 'omni':
            p.changeDynamics(body_id, -1, lateralFriction=0.0, physicsClientId=self.client)
        if spec.kind == 'kinematic':
            body.kin_pose = [x, y, z, yaw]
            body.visible = bool(spec.visible)
            self._place_kinematic(body)
        if spec.grid_texture:
            if self._texture_id() is not None:
                p.changeVisualShape(body_id, -1, textureUniqueId=self._texture,
                                    physicsClientId=self.client)
        return body

    def _texture_id(self):
        if getattr(self, '_texture', None) is None:
            self._texture = p.loadTexture(grid_texture_file(20.0), physicsClientId=self.client)
        return self._texture

    # commands (call from the simulator's thread)
    def set_velocity(self, name, vx, vy, wz):
        """Command a body's velocity: body frame for robots, world for kinematic."""
        values = (float(vx), float(vy), float(wz))
        if not all(math.isfinite(v) for v in values):
            raise ValueError('velocity command must be finite, got %s' % (values,))
        body = self.bodies[name]
        body.cmd = values
        body.cmd_time = self.time

    def set_head(self, name, angle):
        """Command the head yaw (rad), clamped to ``head_joint``'s limits."""
        if not math.isfinite(angle):
            raise ValueError('head angle must be finite, got %r' % angle)
        body = self.bodies[name]
        _, lower, upper = body.joints['head_joint']
        body.head_target = min(max(float(angle), lower), upper)
        return body.head_target

    def set_visible(self, name, visible):
        """Lift a kinematic body out of sight (below the floor) or bring it back."""
        body = self.bodies[name]
        body.visible = bool(visible)
        self._place_kinematic(body)

    def teleport(self, name, x, y):
        """Put a kinematic body at (x, y) at once."""
        body = self.bodies[name]
        body.kin_pose[0], body.kin_pose[1] = float(x), float(y)
        self._place_kinematic(body)

    def _place_kinematic(self, body):
        x, y, z, yaw = body.kin_pose
        p.resetBasePositionAndOrientation(
            body.id, [x, y, z if body.visible else HIDDEN_Z],
            p.getQuaternionFromEuler([0, 0, yaw]), physicsClientId=self.client)

    def reset(self):
        """Put every model back at its spawn pose, at rest (Gazebo's reset_world)."""
        for body in self.bodies.values():
            x, y, z, yaw = body.spec.pose
            p.resetBasePositionAndOrientation(body.id, [x, y, z],
                                              p.getQuaternionFromEuler([0, 0, yaw]),
                                              physicsClientId=self.client)
            p.resetBaseVelocity(body.id, [0, 0, 0], [0, 0, 0], physicsClientId=self.client)
            for j, _, _ in body.joints.values():
                p.resetJointState(body.id, j, 0.0, 0.0, physicsClientId=self.client)
            body.cmd, body.cmd_time, body.head_target = (0.0, 0.0, 0.0), None, 0.0
            if body.kin_pose is not None:
                body.kin_pose = [x, y, z, yaw]
                body.visible = bool(body.spec.visible)
                self._place_kinematic(body)

    # stepping
    def step(self):
        """Apply the commands and advance physics by one time step."""
        for body in self.bodies.values():
            if body.cmd_time is not None and self.time - body.cmd_time > self.cmd_timeout:
                body.cmd, body.cmd_time = (0.0, 0.0, 0.0), None
            kind = body.spec.kind
            if kind == 'diff_drive':
                self._drive_wheels(body)
            elif kind == 'omni':
                self._drive_omni(body)
            elif kind == 'kinematic':
                self._drive_kinematic(body)
        p.stepSimulation(physicsClientId=self.client)
        self.steps += 1

    @property
    def time(self):
        """Simulated time (s) since start."""
        return self.steps * self.time_step

    def _drive_wheels(self, body):
        v, _, w = body.cmd
        spec = body.spec
        half = spec.wheel_separation / 2.0
        targets = {'joint_left_wheel': (v - w * half) / spec.wheel_radius,
                   'joint_right_wheel': (v + w * half) / spec.wheel_radius}
        for name, speed in targets.items():
            p.setJointMotorControl2(body.id, body.joints[name][0], p.VELOCITY_CONTROL,
                                    targetVelocity=speed, force=spec.max_wheel_torque,
                                    physicsClientId=self.client)
        if 'head_joint' in body.joints:
            p.setJointMotorControl2(body.id, body.joints['head_joint'][0], p.POSITION_CONTROL,
                                    targetPosition=body.head_target, force=5.0,
                                    maxVelocity=2.0, physicsClientId=self.client)

    def _drive_omni(self, body):
        vx, vy, wz = body.cmd
        _, quat = p.getBasePositionAndOrientation(body.id, physicsClientId=self.client)
        yaw = yaw_of(quat)
        c, s = math.cos(yaw), math.sin(yaw)
        lin, _ = p.getBaseVelocity(body.id, physicsClientId=self.client)
        p.resetBaseVelocity(body.id, [c * vx - s * vy, s * vx + c * vy, lin[2]], [0, 0, wz],
                            physicsClientId=self.client)

    def _drive_kinematic(self, body):
        vx, vy, wz = body.cmd
        if vx == 0.0 and vy == 0.0 and wz == 0.0:
            return
        pose = body.kin_pose
        pose[0] += vx * self.time_step
        pose[1] += vy * self.time_step
        pose[3] += wz * self.time_step
        self._place_kinematic(body)

    # state
    def pose(self, name):
        """World pose of a body's base: ((x, y, z), (qx, qy, qz, qw))."""
        body = self.bodies[name]
        if body.kin_pose is not None:
            x, y, z, yaw = body.kin_pose
            return (x, y, z if body.visible else HIDDEN_Z), p.getQuaternionFromEuler([0, 0, yaw])
        return p.getBasePositionAndOrientation(body.id, physicsClientId=self.client)

    def twist(self, name):
        """A body's twist in its own frame: ((vx, vy, vz), (wx, wy, wz))."""
        body = self.bodies[name]
        if body.kin_pose is not None:
            vx, vy, wz = body.cmd
            c, s = math.cos(body.kin_pose[3]), math.sin(body.kin_pose[3])
            return (c * vx + s * vy, -s * vx + c * vy, 0.0), (0.0, 0.0, wz)
        lin, ang = p.getBaseVelocity(body.id, physicsClientId=self.client)
        _, quat = p.getBasePositionAndOrientation(body.id, physicsClientId=self.client)
        rot = np.array(p.getMatrixFromQuaternion(quat)).reshape(3, 3)
        return tuple(rot.T.dot(lin)), tuple(rot.T.dot(ang))

    def joint_states(self, name):
        """(names, positions, velocities, efforts) of a body's movable joints."""
        body = self.bodies[name]
        names = [n for n, _ in body.movable]
        idx = [j for _, j in body.movable]
        states = p.getJointStates(body.id, idx, physicsClientId=self.client) if idx else []
        return (names, [s[0] for s in states], [s[1] for s in states], [s[3] for s in states])

    # camera
    def camera_matrices(self, name, link, width, height, hfov_deg, near=0.05, far=40.0):
        """pybullet (view, projection) matrices of a camera on ``link`` looking
        along the link's +x with horizontal field of view ``hfov_deg``."""
        body = self.bodies[name]
        state = p.getLinkState(body.id, body.links[link], computeForwardKinematics=True,
                               physicsClientId=self.client)
        pos, quat = state[4], state[5]
        rot = np.array(p.getMatrixFromQuaternion(quat)).reshape(3, 3)
        forward, up = rot[:, 0], rot[:, 2]
        view = p.computeViewMatrix(pos, (np.asarray(pos) + forward).tolist(), up.tolist())
        # pybullet's fov is vertical: derive it from the horizontal one.
        aspect = float(width) / height
        vfov = math.degrees(2.0 * math.atan(math.tan(math.radians(hfov_deg) / 2.0) / aspect))
        return view, p.computeProjectionMatrixFOV(vfov, aspect, near, far)

    def render_raw(self, width, height, view, proj):
        """pybullet's own getCameraImage, nothing added (the benchmark's yardstick)."""
        return p.getCameraImage(width, height, view, proj, renderer=self._renderer,
                                flags=p.ER_NO_SEGMENTATION_MASK, physicsClientId=self.client)

    def render(self, name, link, width, height, hfov_deg):
        """Render from ``link`` of body ``name``; an (height, width, 4) uint8 RGBA
        array (pybullet's own buffer, not copied)."""
        view, proj = self.camera_matrices(name, link, width, height, hfov_deg)
        rgba = self.render_raw(width, height, view, proj)[2]
        return np.asarray(rgba, dtype=np.uint8).reshape(height, width, 4)

    def close(self):
        if self._egl_plugin is not None:
            p.unloadPlugin(self._egl_plugin, physicsClientId=self.client)
        p.disconnect(self.client)

"""A model in the world: what a plugin is given as ``self.model`` (no ROS).

A :class:`Model` is one loaded URDF. It answers where it is (base and link
poses in the URDF frames, its twist, its joints) and takes what plugins do to
it (joint motors, base velocity, a new pose). Three kinds of body:

* static (``<gazebo><static>true</static>``): fixed where it was spawned;
* kinematic (gravity off on the root link: ``<gazebo reference="root">
  <gravity>0</gravity>``): no physics acts on it; it is moved by setting
  its pose (the ball). Below the ground (z < 0) it is hidden from cameras;
* dynamic: everything else, moved by physics (the robots).

A dynamic model that nothing drives rests while still (:mod:`.resting`).

A model a ball script holds (:meth:`Model.hold`, :mod:`.scripted_ball`) is
kinematic and moved by the script alone: what others do to it
(:meth:`set_pose`, :meth:`move_kinematic`, :meth:`set_world_velocity`) is
ignored, and the placements among it counted in :attr:`ignored`.
"""
import math

import numpy as np
from exp_assignment2.sim.bullet import p

from exp_assignment2.geometry import all_finite
from exp_assignment2.sim import resting
from exp_assignment2.sim.poses import in_region

HIDDEN_Z = -50.0   # where a hidden body is put, far below every camera's view
# Gazebo's 1 m grid (rendering::Grid): a GUI visual, drawn in gzclient's view and
# not in a camera sensor's images; an SDF world's ground plane has it
GUI_GRID = 'gui'


class Model(object):
    """A spawned model (see the module docstring).

    :param physics: the :class:`~exp_assignment2.sim.physics.Physics` world
    :param urdf: its parsed :class:`~exp_assignment2.sim.urdf.UrdfModel`
    :param pose: spawn pose (x, y, z, roll, pitch, yaw) of the URDF root frame
    :param namespace: the robot namespace its plugins publish under
    """

    def __init__(self, physics, name, urdf, pose, namespace='', grid=False, hidden=False):
        self.physics, self.client = physics, physics.client
        # True: pybullet's grid texture, seen by every camera; GUI_GRID: Gazebo's
        # grid, a GUI visual its camera sensors do not see
        self.name, self.urdf = name, urdf
        self.grid = GUI_GRID if grid == GUI_GRID else bool(grid)
        self.namespace = namespace.strip('/')
        self.spawn_pose = tuple(float(v) for v in pose)
        self.static = urdf.gazebo.static
        self.kinematic = not self.static and urdf.root in urdf.gazebo.gravity_off
        x, y, z, roll, pitch, yaw = self.spawn_pose
        self._quat = p.getQuaternionFromEuler([roll, pitch, yaw])
        self.body = physics.load(name, urdf, (x, y, z), self._quat,
                                 fixed=self.static or self.kinematic)
        self.id = self.body.id
        self.spawn_hidden = self.hidden = bool(hidden) and self.kinematic
        self.placed = 0        # times put somewhere by a command (set_model/link_state)
        self.removed = False
        self.script = None     # the ball script holding it (facts), else None
        self.ignored = 0       # placements refused while a script holds it
        self._kinematic_pose = [x, y, z, yaw]
        for link, (mu1, mu2) in urdf.gazebo.friction.items():
            if link in self.body.links and mu1 is not None:
                p.changeDynamics(self.id, self.body.links[link], lateralFriction=mu1,
                                 physicsClientId=self.client)
        if self.grid is True:
            p.changeVisualShape(self.id, -1, textureUniqueId=physics.grid_texture(),
                                physicsClientId=self.client)
        if self.hidden:
            self._place()
        self.may_rest = resting.may_rest(self)

    @property
    def base_frame(self):
        """The URDF root link's name."""
        return self.urdf.root

    def topic(self, name):
        """A topic under the model's namespace (``name`` absolute stays absolute)."""
        if name.startswith('/'):
            return name
        return '/%s/%s' % (self.namespace, name) if self.namespace else '/' + name

    # where it is
    def pose(self):
        """World pose of the URDF root frame: ((x, y, z), (qx, qy, qz, qw))."""
        if self.kinematic:
            x, y, z, yaw = self._kinematic_pose
            return (x, y, z), tuple(p.getQuaternionFromEuler([0, 0, yaw]))
        com = p.getBasePositionAndOrientation(self.id, physicsClientId=self.client)
        inv = p.invertTransform(*self.body.inertial)
        pos, quat = p.multiplyTransforms(com[0], com[1], inv[0], inv[1])
        return tuple(pos), tuple(quat)

    def yaw(self):
        return p.getEulerFromQuaternion(self.pose()[1])[2]

    def world_twist(self):
        """((vx, vy, vz), (wx, wy, wz)) in the world frame (dynamic bodies)."""
        if self.kinematic or self.static:
            return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
        lin, ang = p.getBaseVelocity(self.id, physicsClientId=self.client)
        return tuple(lin), tuple(ang)

    def twist(self):
        """The twist in the model's own frame: ((vx, vy, vz), (wx, wy, wz))."""
        if self.kinematic:
            return self._kinematic_twist
        lin, ang = self.world_twist()
        _, quat = p.getBasePositionAndOrientation(self.id, physicsClientId=self.client)
        rot = np.array(p.getMatrixFromQuaternion(quat)).reshape(3, 3)
        return tuple(rot.T.dot(lin)), tuple(rot.T.dot(ang))

    _kinematic_twist = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))

    def link_pose(self, link):
        """World pose of a link's URDF frame (KeyError for an unknown link)."""
        index = self.body.links[link]
        if index < 0:
            return self.pose()
        state = p.getLinkState(self.id, index, computeForwardKinematics=True,
                               physicsClientId=self.client)
        return tuple(state[4]), tuple(state[5])

    def relative_pose(self, parent, child):
        """Pose of link ``child``'s frame in link ``parent``'s: (position, quaternion)."""
        inv = p.invertTransform(*self.link_pose(parent))
        pos, quat = p.multiplyTransforms(inv[0], inv[1], *self.link_pose(child))
        return tuple(pos), tuple(quat)

    def has_joint(self, name):
        return name in self.body.joints

    def joint_index(self, name):
        return self.body.joints[name][0]

    def joint_limits(self, name):
        """(lower, upper) of a joint; (-inf, inf) for continuous ones."""
        _, lower, upper, _ = self.body.joints[name]
        joint = self.urdf.joints[name]
        if joint.type == 'continuous' or lower > upper:
            return -math.inf, math.inf
        return lower, upper

    @property
    def movable_joints(self):
        return [name for name, _ in self.body.movable]

    def joint_states(self, names=None):
        """(names, positions, velocities, efforts) of ``names`` (default: every movable joint)."""
        names = self.movable_joints if names is None else list(names)
        idx = [self.body.joints[n][0] for n in names]
        states = p.getJointStates(self.id, idx, physicsClientId=self.client) if idx else []
        return (names, [s[0] for s in states], [s[1] for s in states],
                [s[3] for s in states])

    def trouble(self, region):
        """None while the pose and velocity are finite and the body is within
        ``region`` (:func:`~.poses.world_region`), else what went wrong."""
        pos, quat = p.getBasePositionAndOrientation(self.id, physicsClientId=self.client)
        lin, ang = p.getBaseVelocity(self.id, physicsClientId=self.client)
        if not all_finite(*pos, *quat, *lin, *ang):
            return 'had a non-finite pose'
        if not in_region(region, pos):
            return 'left the world at (%.1f, %.1f, %.1f)' % tuple(pos)
        return None

    # what plugins do to it
    def set_joint_velocity(self, name, velocity, max_force):
        """Drive a joint's motor at ``velocity`` (rad/s) with at most ``max_force``."""
        resting.wake(self)
        p.setJointMotorControl2(self.id, self.joint_index(name), p.VELOCITY_CONTROL,
                                targetVelocity=velocity, force=max_force,
                                physicsClientId=self.client)

    def set_joint_position(self, name, position, max_force, max_velocity):
        """Drive a joint's motor to ``position`` (rad or m)."""
        resting.wake(self)
        p.setJointMotorControl2(self.id, self.joint_index(name), p.POSITION_CONTROL,
                                targetPosition=position, force=max_force,
                                maxVelocity=max_velocity, physicsClientId=self.client)

    def set_joint_state(self, name, position):
        """Put a joint at ``position`` at once, at rest (Gazebo's set_model_configuration)."""
        resting.wake(self)
        p.resetJointState(self.id, self.joint_index(name), position, 0.0,
                          physicsClientId=self.client)

    def set_friction(self, link, lateral, spinning=0.0, rolling=0.0):
        p.changeDynamics(self.id, self.body.links[link], lateralFriction=lateral,
                         spinningFriction=spinning, rollingFriction=rolling,
                         physicsClientId=self.client)

    def set_world_velocity(self, linear, angular):
        """A dynamic body's base velocity (world frame), as Gazebo's SetLinearVel."""
        if self.script is not None:
            return
        resting.wake(self, linear, angular)
        p.resetBaseVelocity(self.id, list(linear), list(angular), physicsClientId=self.client)

    def move_kinematic(self, dx, dy, dyaw, twist=None):
        """Move a kinematic body by (dx, dy) (world) and turn it by dyaw."""
        if self.script is not None:
            return
        pose = self._kinematic_pose
        pose[0], pose[1], pose[3] = pose[0] + dx, pose[1] + dy, pose[3] + dyaw
        if twist is not None:
            self._kinematic_twist = twist
        self._place()

    def set_pose(self, position, quaternion=None, twist=None):
        """Put the model's URDF root frame at ``position`` (orientation kept if
        None), at rest unless ``twist`` ((linear), (angular), world frame)
        is given. A kinematic body below the ground (z < 0) is hidden. A
        body a script holds stays where it is (the command is counted)."""
        if self.script is not None:
            self.ignored += 1
            return
        self.placed += 1
        if quaternion is None:
            quaternion = self.pose()[1]
        if self.kinematic:
            self._kinematic_pose = [position[0], position[1], position[2],
                                    p.getEulerFromQuaternion(quaternion)[2]]
            self.hidden = position[2] < 0.0
            self._place()
            return
        lin, ang = twist if twist is not None else ((0, 0, 0), (0, 0, 0))
        resting.wake(self, lin, ang)
        com = p.multiplyTransforms(position, quaternion, *self.body.inertial)
        p.resetBasePositionAndOrientation(self.id, com[0], com[1], physicsClientId=self.client)
        p.resetBaseVelocity(self.id, list(lin), list(ang), physicsClientId=self.client)

    def _place(self):
        x, y, z, yaw = self._kinematic_pose
        p.resetBasePositionAndOrientation(
            self.id, [x, y, HIDDEN_Z if self.hidden else z],
            p.getQuaternionFromEuler([0, 0, yaw]), physicsClientId=self.client)

    # a ball script's
    def hold(self, facts):
        """From now on the script described by ``facts`` (plain data) moves
        this body, kinematically, and nothing else does."""
        if not self.kinematic:      # a dynamic sphere: no physics acts on it any more
            resting.wake(self)
            self.may_rest = False
            (x, y, z), quat = self.pose()
            self._kinematic_pose = [x, y, z, p.getEulerFromQuaternion(quat)[2]]
            p.changeDynamics(self.id, -1, mass=0.0, physicsClientId=self.client)
            p.resetBaseVelocity(self.id, [0, 0, 0], [0, 0, 0], physicsClientId=self.client)
            self.kinematic = True
        self.script = facts

    def play(self, x, y, z, hidden, velocity):
        """Where the script puts it (not a command: not counted); ``velocity``
        (vx, vy) in the world frame, reported in its own."""
        yaw = self._kinematic_pose[3]
        c, s = math.cos(yaw), math.sin(yaw)
        vx, vy = velocity
        self._kinematic_pose = [x, y, z, yaw]
        self._kinematic_twist = ((c * vx + s * vy, -s * vx + c * vy, 0.0), (0.0, 0.0, 0.0))
        self.hidden = bool(hidden)
        self._place()

    def collision_box(self, link):
        """((x0, y0, z0), (x1, y1, z1)): the world box around a link's
        collisions, None when it has none."""
        if not self.urdf.links[link].collisions:
            return None
        low, high = p.getAABB(self.id, self.body.links[link], physicsClientId=self.client)
        return tuple(low), tuple(high)

    def reset(self):
        """Back at the spawn pose, at rest, every joint at zero (reset_world);
        a body a script holds stays where the script has it."""
        x, y, z, roll, pitch, yaw = self.spawn_pose
        for j, _, _, _ in self.body.joints.values():
            p.resetJointState(self.id, j, 0.0, 0.0, physicsClientId=self.client)
        if self.script is not None:
            return
        if self.kinematic:
            self._kinematic_pose = [x, y, z, yaw]
            self._kinematic_twist = Model._kinematic_twist
            self.hidden = self.spawn_hidden
            self._place()
            return
        resting.wake(self)
        com = p.multiplyTransforms([x, y, z], self._quat, *self.body.inertial)
        p.resetBasePositionAndOrientation(self.id, com[0], com[1], physicsClientId=self.client)
        p.resetBaseVelocity(self.id, [0, 0, 0], [0, 0, 0], physicsClientId=self.client)

    def remove(self):
        self.removed = True
        self.physics.remove(self.id)

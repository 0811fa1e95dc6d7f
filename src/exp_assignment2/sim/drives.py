"""What moves the bodies: drives and joint controllers, with limits (no ROS).

Each takes commands (validated: non-finite values raise ``ValueError``,
finite ones beyond a limit are clamped and reported) and applies them before
every physics step. Velocity commands older than ``cmd_timeout`` s of
simulated time stop the body (0: keep the last one, as Gazebo's diff drive).
Joint and link names come from the world description or the URDF.
"""
import math

from exp_assignment2.sim.bullet import p

from exp_assignment2.geometry import all_finite, cap_norm, clamp
from exp_assignment2.grammar import show_number, show_numbers
from exp_assignment2.sim import urdf


class VelocityDrive(object):
    """Command bookkeeping shared by the drives: limits, timeout, reset."""

    def __init__(self, physics, name, options):
        self.physics, self.name, self.options = physics, name, options
        self.body = physics.bodies[name]
        self.max_linear, self.max_angular = options['max_linear'], options['max_angular']
        self.cmd_timeout = options['cmd_timeout']
        self.reset()

    def reset(self):
        self.cmd, self.cmd_time = (0.0, 0.0, 0.0), None

    def command(self, vx, vy, wz):
        """Take a velocity command; True when it had to be clamped to the limits."""
        if not all_finite(vx, vy, wz):
            raise ValueError('velocity command %s is not finite' % show_numbers((vx, vy, wz)))
        vx, vy, wz = float(vx), float(vy), float(wz)
        over = (math.hypot(vx, vy) > self.max_linear * (1 + 1e-6)
                or abs(wz) > self.max_angular * (1 + 1e-6))
        if over:
            vx, vy = cap_norm(vx, vy, self.max_linear)
            wz = clamp(wz, self.max_angular)
        self.cmd, self.cmd_time = (vx, vy, wz), self.physics.time
        return over

    def current(self):
        """The command in force now (zero once it is older than cmd_timeout)."""
        if (self.cmd_time is not None and self.cmd_timeout > 0
                and self.physics.time - self.cmd_time > self.cmd_timeout):
            self.reset()
        return self.cmd

    @property
    def limits(self):
        return 'at most %g m/s and %g rad/s' % (self.max_linear, self.max_angular)


class DiffDrive(VelocityDrive):
    """Two driven wheels (``linear.x``, ``angular.z``), wired as the URDF says.

    Wheel joints, radius and separation come from the world options or else
    from the URDF's Gazebo diff-drive plugin. ``turn_sign`` is +1 when a
    positive ``angular.z`` turns the robot left (REP 103), -1 when the wheels
    are wired the other way round (the original course robot).
    """

    def __init__(self, physics, name, options):
        body = physics.bodies[name]
        merged = dict(urdf.gazebo_diff_drive(body.urdf))
        merged.update({k: v for k, v in options.items() if v is not None})
        for key in ('left_joint', 'right_joint', 'wheel_radius', 'wheel_separation'):
            if merged.get(key) is None:
                raise ValueError('model %s: diff_drive needs %s (in the world or the URDF\'s '
                                 'Gazebo diff-drive plugin)' % (name, key))
        VelocityDrive.__init__(self, physics, name, merged)
        self.wheels = []
        for key in ('left_joint', 'right_joint'):
            if merged[key] not in body.joints:
                raise ValueError('model %s: diff_drive %s %r is not a joint of its URDF'
                                 % (name, key, merged[key]))
            self.wheels.append(body.joints[merged[key]][0])
        left_y = urdf.joint_origin(body.urdf, merged['left_joint'])[1]
        right_y = urdf.joint_origin(body.urdf, merged['right_joint'])[1]
        self.turn_sign = 1 if left_y > right_y else -1    # see urdf.diff_drive_turn_sign
        self.radius, self.separation = merged['wheel_radius'], merged['wheel_separation']
        self.torque = merged['wheel_torque']
        client = physics.client
        # Wheels grip; everything else that touches the ground (a caster) slides.
        for index in [-1] + [j for j, _, _, _ in body.joints.values()]:
            grip = index in self.wheels
            p.changeDynamics(body.id, index, lateralFriction=1.0 if grip else 0.0,
                             spinningFriction=0.0 if not grip else 0.001,
                             rollingFriction=0.0, physicsClientId=client)

    def command(self, vx, vy, wz):
        # like Gazebo's diff drive, linear.y is not a degree of freedom: ignored
        return VelocityDrive.command(self, vx, 0.0, wz)

    def apply(self):
        v, _, w = self.current()
        half = self.separation / 2.0
        for index, speed in zip(self.wheels, (v - w * half, v + w * half)):
            p.setJointMotorControl2(self.body.id, index, p.VELOCITY_CONTROL,
                                    targetVelocity=speed / self.radius, force=self.torque,
                                    physicsClientId=self.physics.client)


class PlanarMove(VelocityDrive):
    """Gazebo's planar_move: ``linear.x``, ``linear.y`` and ``angular.z`` in the
    body's frame. ``kinematic`` bodies (the ball) move with no physics; the
    others (MiRo) have their base velocity set every step. Neither leaves the
    world's bounds."""

    def __init__(self, physics, name, options, bounds):
        VelocityDrive.__init__(self, physics, name, options)
        self.bounds = bounds
        if not options['kinematic']:
            p.changeDynamics(self.body.id, -1, lateralFriction=0.0,
                             physicsClientId=physics.client)

    def world_velocity(self, yaw):
        vx, vy, wz = self.current()
        c, s = math.cos(yaw), math.sin(yaw)
        return c * vx - s * vy, s * vx + c * vy, wz

    def apply(self):
        x_min, x_max, y_min, y_max = self.bounds
        body, dt = self.body, self.physics.time_step
        if body.kinematic is not None:
            pose = body.kinematic
            vx, vy, wz = self.world_velocity(pose[3])
            if vx == vy == wz == 0.0:
                return
            pose[0] = min(max(pose[0] + vx * dt, x_min), x_max)
            pose[1] = min(max(pose[1] + vy * dt, y_min), y_max)
            pose[3] += wz * dt
            self.physics.place_kinematic(self.name)
            return
        (x, y, _), quat = self.physics.base_pose(self.name)
        vx, vy, wz = self.world_velocity(p.getEulerFromQuaternion(quat)[2])
        # at a bound, nothing moves further out
        if (x <= x_min and vx < 0) or (x >= x_max and vx > 0):
            vx = 0.0
        if (y <= y_min and vy < 0) or (y >= y_max and vy > 0):
            vy = 0.0
        lin, _ = p.getBaseVelocity(body.id, physicsClientId=self.physics.client)
        self.physics.set_base_velocity(self.name, [vx, vy, lin[2]], [0.0, 0.0, wz])


class JointPosition(object):
    """A position-controlled joint (the head): commands clamped to its limits."""

    def __init__(self, physics, name, options):
        self.physics, self.body = physics, physics.bodies[name]
        joint = options['joint']
        if joint is None or joint not in self.body.joints:
            raise ValueError('model %s: joint_position needs a joint of its URDF, got %r'
                             % (name, joint))
        self.joint = joint
        self.index, self.lower, self.upper, _ = self.body.joints[joint]
        self.max_velocity, self.effort = options['max_velocity'], options['effort']
        self.reset()

    def reset(self):
        self.target = 0.0
        self.dirty = True

    def command(self, angle):
        """Set the target angle; returns the clamped target."""
        if not all_finite(angle):
            raise ValueError('joint position command %s is not finite' % show_number(angle))
        self.target = min(max(float(angle), self.lower), self.upper)
        self.dirty = True
        return self.target

    def apply(self):
        if self.dirty:   # the motor keeps its target: set it only when it changes
            p.setJointMotorControl2(self.body.id, self.index, p.POSITION_CONTROL,
                                    targetPosition=self.target, force=self.effort,
                                    maxVelocity=self.max_velocity,
                                    physicsClientId=self.physics.client)
            self.dirty = False


class Height(object):
    """A kinematic body's height (the ball's): below 0 it is under the ground,
    hidden from every camera, as the original's set_link_state left it."""

    def __init__(self, physics, name, options):
        self.physics, self.name, self.body = physics, name, physics.bodies[name]
        if self.body.kinematic is None:
            raise ValueError('model %s: height needs a kinematic planar_move body' % name)
        self.max_z = options['max_z']

    def reset(self):
        pass

    def command(self, z):
        """Set the height; returns the height used (at most max_z)."""
        if not all_finite(z):
            raise ValueError('height command %s is not finite' % show_number(z))
        z = min(float(z), self.max_z)
        self.body.kinematic[2] = z
        self.body.hidden = z < 0.0
        self.physics.place_kinematic(self.name)
        return z

    def apply(self):
        pass

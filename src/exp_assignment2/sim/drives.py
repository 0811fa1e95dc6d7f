"""What moves the bodies: the drives and joint controllers behind the
plugins, with their limits (no ROS).

Each takes commands (validated: non-finite values raise ``ValueError``,
finite ones beyond a limit are clamped and reported) and applies them to a
:class:`~exp_assignment2.sim.model.Model` before physics steps. Velocity
commands older than ``cmd_timeout`` s of simulated time stop the body (0:
keep the last one forever, as Gazebo's plugins do).
"""
import math

from exp_assignment2.geometry import all_finite, cap_norm, clamp
from exp_assignment2.grammar import show_number, show_numbers
from exp_assignment2.sim import releases


class VelocityCommand(object):
    """The velocity command in force: limits, age and reset.

    :param now: a callable giving simulated time (s)
    """

    def __init__(self, now, max_linear=2.0, max_angular=3.0, cmd_timeout=0.5):
        self.now, self.max_linear, self.max_angular = now, max_linear, max_angular
        self.cmd_timeout = cmd_timeout
        self.taken = 0          # commands taken (finite ones), ever: who drives this body
        self.reset()

    def reset(self):
        self.cmd, self.cmd_time = (0.0, 0.0, 0.0), None

    def command(self, vx, vy, wz):
        """Take a command (body frame); True when it had to be clamped."""
        if not all_finite(vx, vy, wz):
            raise ValueError('velocity command %s is not finite' % show_numbers((vx, vy, wz)))
        vx, vy, wz = float(vx), float(vy), float(wz)
        over = (math.hypot(vx, vy) > self.max_linear * (1 + 1e-6)
                or abs(wz) > self.max_angular * (1 + 1e-6))
        if over:
            vx, vy = cap_norm(vx, vy, self.max_linear)
            wz = clamp(wz, self.max_angular)
        self.cmd, self.cmd_time = (vx, vy, wz), self.now()
        self.taken += 1
        return over

    def current(self):
        """(vx, vy, wz) now: zero once the command is older than cmd_timeout
        (or from the future: time went back)."""
        if self.cmd_time is not None and self.cmd_timeout > 0:
            age = self.now() - self.cmd_time
            if age > self.cmd_timeout or age < 0:
                self.reset()
        return self.cmd

    @property
    def limits(self):
        return 'at most %g m/s and %g rad/s' % (self.max_linear, self.max_angular)


DIFF_DRIVE_PLUGIN = 'libgazebo_ros_diff_drive.so'


def wheel_forward(urdf, joint):
    """(lateral position, forward speed per unit rate) of a wheel joint: a
    wheel turning about axis ``a`` (root frame) at rate w rolls its hub
    forward at w * r * a_y, and sits at y on the robot."""
    position, axis = urdf.joint_axis_in_root(joint)
    return position[1], axis[1]


def turn_sign(urdf, left, right):
    """+1 when a positive angular.z turns the robot left (REP 103), -1 when
    it turns right (wheels named the other way round), 0 when it does not
    turn: the left joint turns at (v - w s/2) / r, the right at (v + w s/2) / r."""
    (y_left, f_left), (y_right, f_right) = wheel_forward(urdf, left), wheel_forward(urdf, right)
    if abs(y_left - y_right) < 1e-9:
        return 0
    rate = (-f_left - f_right) / (y_right - y_left)    # yaw rate per unit angular.z
    return 0 if abs(rate) < 1e-9 else (1 if rate > 0 else -1)


def diff_drive_turn_sign(urdf, release=None):
    """:func:`turn_sign` of a parsed URDF's Gazebo diff drive as ``release``
    runs it (a :class:`~exp_assignment2.sim.releases.Release`; None: the
    environment's, :func:`~exp_assignment2.sim.releases.choose`); ValueError
    if it has none."""
    plugin = next((p for p in urdf.gazebo.plugins if p.filename == DIFF_DRIVE_PLUGIN), None)
    if plugin is None:
        raise ValueError('no Gazebo diff-drive plugin (%s)' % DIFF_DRIVE_PLUGIN)
    left = plugin.options.get('leftJoint') or 'left_joint'
    right = plugin.options.get('rightJoint') or 'right_joint'
    for joint in (left, right):
        if joint not in urdf.joints:
            raise ValueError('the diff drive names joint %r, which the URDF lacks' % joint)
    release = release or releases.choose()
    legacy, _ = release.boolean(plugin.options.get('legacyMode'), None)
    sign = turn_sign(urdf, left, right)
    return -sign if release.swaps_wheels(legacy) else sign


class DiffDrive(object):
    """Gazebo's diff drive: the joint named by leftJoint turns at
    (v - w * s / 2) / r and rightJoint at (v + w * s / 2) / r (s:
    wheelSeparation, r: wheelDiameter / 2), or the other way round when
    ``swapped`` (Kinetic's legacyMode, see :mod:`.releases`). Which way the
    robot then turns is physics: where those joints are and which way their
    axes point.

    ``acceleration`` (wheelAcceleration, m/s², 0: none, the default in
    every release): as Gazebo's UpdateChild, while neither wheel is within
    0.01 m/s of its speed, the speed asked of each wheel moves towards its
    target by at most ``acceleration * dt`` from what it asked before.
    """

    def __init__(self, model, left, right, separation, diameter, torque, command,
                 swapped=False, acceleration=0.0):
        for joint in (left, right):
            if not model.has_joint(joint):
                raise ValueError('no joint %r in the model' % joint)
        self.model, self.joints, self.command = model, (left, right), command
        self.half, self.radius, self.torque = separation / 2.0, diameter / 2.0, torque
        self.swapped, self.acceleration = bool(swapped), acceleration
        self.asked = [0.0, 0.0]      # Gazebo's wheel_speed_instr_

    def turn_sign(self):
        """See :func:`turn_sign` (the swap included)."""
        sign = turn_sign(self.model.urdf, *self.joints)
        return -sign if self.swapped else sign

    def wheel_speeds(self):
        """(left, right) surface speeds (m/s) the command asks of the wheels."""
        v, _, w = self.command.current()
        if self.swapped:
            w = -w
        return v - w * self.half, v + w * self.half

    def apply(self, dt=0.0):
        """Set the wheels; ``dt``: s since the last update (for wheelAcceleration)."""
        speeds = self.wheel_speeds()
        if self.acceleration:
            _, _, rates, _ = self.model.joint_states(self.joints)
            current = [rate * self.radius for rate in rates]
            if not any(abs(t - c) < 0.01 for t, c in zip(speeds, current)):
                step = abs(self.acceleration) * dt
                self.asked = [a + min(max(t - c, -step), step)
                              for a, t, c in zip(self.asked, speeds, current)]
                speeds = self.asked
        for joint, speed in zip(self.joints, speeds):
            self.model.set_joint_velocity(joint, speed / self.radius, self.torque)

    def reset(self):
        self.asked = [0.0, 0.0]


class SkidSteer(object):
    """Gazebo's skid steer drive: a :class:`DiffDrive` for each pair of
    wheels (front and rear), both on one command, as gazebo_ros_skid_steer_drive
    turns its left joints at (v - w * s / 2) / r and its right ones at
    (v + w * s / 2) / r."""

    def __init__(self, model, left, right, separation, diameter, torque, command):
        self.pairs = [DiffDrive(model, l, r, separation, diameter, torque, command)
                      for l, r in zip(left, right)]
        self.model, self.command = model, command
        self.joints = tuple(left) + tuple(right)
        self.radius, self.half = self.pairs[0].radius, self.pairs[0].half

    def turn_sign(self):
        return self.pairs[0].turn_sign()

    def apply(self, dt=0.0):
        for pair in self.pairs:
            pair.apply(dt)

    def reset(self):
        pass


class EncoderOdometry(object):
    """Gazebo's diff drive odometry from the wheels (odometrySource encoder):
    dead reckoning from the two joints' rates, every step. ``swapped``:
    Kinetic's legacy mode, which turns by (left - right) / s as its wheels do;
    ``twist_in_child_frame``: Melodic's and Noetic's twist (the forward speed),
    else Kinetic's (dx/dt and dy/dt of the odometry frame, #719)."""

    def __init__(self, radius, separation, swapped=False, twist_in_child_frame=True):
        self.radius, self.separation = radius, separation
        self.swapped, self.child_frame = bool(swapped), bool(twist_in_child_frame)
        self.reset()

    def reset(self):
        self.pose, self.twist = [0.0, 0.0, 0.0], (0.0, 0.0, 0.0)

    def step(self, left_rate, right_rate, dt):
        """Integrate ``dt`` s of the leftJoint's and rightJoint's rates (rad/s)."""
        sl, sr = left_rate * self.radius * dt, right_rate * self.radius * dt
        b, travelled = self.separation, sl + sr
        turned = sl - sr if self.swapped else sr - sl
        x, y, theta = self.pose
        heading = theta + turned / (2.0 * b)
        dx, dy = travelled / 2.0 * math.cos(heading), travelled / 2.0 * math.sin(heading)
        self.pose = [x + dx, y + dy, theta + turned / b]
        if self.child_frame:
            self.twist = (math.copysign(math.hypot(dx, dy), travelled) / dt, 0.0,
                          turned / b / dt)
        else:
            self.twist = (dx / dt, dy / dt, turned / b / dt)


class PlanarMove(object):
    """Gazebo's planar_move: ``linear.x``, ``linear.y`` and ``angular.z`` in
    the body's frame, set as the body's velocity. Kinematic bodies (the
    ball) are moved by the command alone; the others (MiRo) get their base
    velocity set every step. Neither leaves ``bounds``."""

    def __init__(self, model, command, bounds, time_step):
        self.model, self.command, self.bounds, self.dt = model, command, bounds, time_step

    def world_velocity(self, yaw):
        vx, vy, wz = self.command.current()
        c, s = math.cos(yaw), math.sin(yaw)
        return c * vx - s * vy, s * vx + c * vy, wz

    def apply(self):
        x_min, x_max, y_min, y_max = self.bounds
        (x, y, _), _ = self.model.pose()
        vx, vy, wz = self.world_velocity(self.model.yaw())
        # at a bound, nothing moves further out
        if (x <= x_min and vx < 0) or (x >= x_max and vx > 0):
            vx = 0.0
        if (y <= y_min and vy < 0) or (y >= y_max and vy > 0):
            vy = 0.0
        if self.model.kinematic:
            if vx or vy or wz:
                dx = min(max(x + vx * self.dt, x_min), x_max) - x
                dy = min(max(y + vy * self.dt, y_min), y_max) - y
                self.model.move_kinematic(dx, dy, wz * self.dt,
                                          twist=(self.command.current()[:2] + (0.0,),
                                                 (0.0, 0.0, wz)))
            else:
                self.model.move_kinematic(0.0, 0.0, 0.0,
                                          twist=((0.0, 0.0, 0.0), (0.0, 0.0, 0.0)))
            return
        (lin, _) = self.model.world_twist()
        self.model.set_world_velocity((vx, vy, lin[2]), (0.0, 0.0, wz))


class JointPosition(object):
    """A position-controlled joint (the head): targets clamped to the joint's
    limits, reached at up to ``max_velocity`` with at most ``effort``."""

    def __init__(self, model, joint, max_velocity=2.0, effort=5.0):
        if not model.has_joint(joint):
            raise ValueError('no joint %r in the model' % joint)
        self.model, self.joint = model, joint
        self.lower, self.upper = model.joint_limits(joint)
        self.max_velocity, self.effort = max_velocity, effort
        self.reset()

    def reset(self):
        self.target, self.dirty = 0.0, True

    def command(self, position):
        """Set the target; returns the clamped target."""
        if not all_finite(position):
            raise ValueError('joint position command %s is not finite' % show_number(position))
        self.target = min(max(float(position), self.lower), self.upper)
        self.dirty = True
        return self.target

    def apply(self):
        if self.dirty:   # the motor keeps its target: set it only when it changes
            self.model.set_joint_position(self.joint, self.target, self.effort,
                                          self.max_velocity)
            self.dirty = False

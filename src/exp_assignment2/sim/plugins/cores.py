"""The drive plugins without their ROS topics (no rospy): Gazebo's options
read, the drive built, commands applied at the update rate. The ROS plugins
(:mod:`.drive`) add the command topic and odometry; the unit tests and the
benchmark register these cores under the same file names and drive the
models by hand, through the very same stepping code.
"""
import re

from exp_assignment2.sim.drives import (DiffDrive, EncoderOdometry, PlanarMove, SkidSteer,
                                        VelocityCommand)
from exp_assignment2.sim.plugins.base import Plugin, PluginError

ODOMETRY_SOURCES = ('world', 'encoder')


class Every(object):
    """Something due every ``1 / rate`` s of simulated time (rate 0: every step),
    as Gazebo's plugins count it; time going back makes it due at once."""

    def __init__(self, rate, now):
        self.period = 1.0 / rate if rate > 0 else 0.0
        self.now, self.next = now, now()

    def due(self):
        t = self.now()
        if t < self.next - self.period - 1e-9:     # time went back (reset_simulation)
            self.next = t
        if t + 1e-9 < self.next:
            return False
        self.next += self.period
        if self.next <= t:                          # far behind: count from now
            self.next = t + self.period
        return True

    def reset(self):
        self.next = self.now()


def velocity_command(plugin, timeout=None):
    """A :class:`~exp_assignment2.sim.drives.VelocityCommand` with the host's
    limits (settings ``max_linear``, ``max_angular``). How long a command
    holds: ``timeout`` s when the plugin itself says (Noetic's planar_move
    ``cmdTimeout``), else the host's ``cmd_timeout``, else for ever (0), as
    Gazebo's drive plugins keep the last ``cmd_vel`` until another comes."""
    settings = plugin.engine.settings
    hold = float(settings.get('cmd_timeout', 0.0)) if timeout is None else timeout
    return VelocityCommand(lambda: plugin.engine.time,
                           max_linear=float(settings.get('max_linear', 2.0)),
                           max_angular=float(settings.get('max_angular', 3.0)),
                           cmd_timeout=hold)


class DriveCore(Plugin):
    """What the drive plugins share: the velocity command they take, on their
    ``commandTopic`` (default ``cmd_vel``) under the robot namespace."""

    def command_topic(self):
        return self.topic(self.options.text('commandTopic', 'cmd_vel'))

    def facts(self):
        return dict(Plugin.facts(self), drive=True, command=self.command_topic(),
                    joints=list(getattr(self.drive, 'joints', ())))

    @property
    def commands_taken(self):
        return self.command.taken


class DiffDriveCore(DriveCore):
    """``libgazebo_ros_diff_drive.so`` without ROS: leftJoint, rightJoint,
    wheelSeparation, wheelDiameter, wheelTorque, updateRate, odometrySource
    (world|encoder), and legacyMode as the engine's ROS release reads it
    (:mod:`~exp_assignment2.sim.releases`: Kinetic swaps the wheels, true
    when absent; Melodic and Noetic accept the tag and do not read it)."""

    FILENAMES = ('libgazebo_ros_diff_drive.so',)

    def load(self):
        o, release = self.options, self.engine.release
        self.command = velocity_command(self)
        text = o.raw('legacyMode')
        legacy, understood = release.boolean(text, None)
        if release.reads_legacy_mode and legacy is None:    # Gazebo's ROS_ERROR, ROS_WARN
            (self.engine.log.error if understood else self.engine.log.warn)(
                '%s: %s, defaults to %s (ROS %s): the wheels are swapped, as in an old '
                'package; set it to false for a new package'
                % (o.where, 'missing <legacyMode>' if understood else
                   '<legacyMode> %r is not true or false' % text,
                   str(release.legacy_mode).lower(), release.name))
        try:
            self.drive = DiffDrive(self.model, o.text('leftJoint', 'left_joint'),
                                   o.text('rightJoint', 'right_joint'),
                                   o.number('wheelSeparation', 0.34),
                                   o.number('wheelDiameter', 0.15, nonzero=True),
                                   o.number('wheelTorque', 5.0, minimum=0.0), self.command,
                                   swapped=release.swaps_wheels(legacy),
                                   acceleration=o.number('wheelAcceleration', 0.0))
        except PluginError:
            raise
        except ValueError as exc:   # Gazebo: ROS_FATAL and gzthrow, the plugin does not run
            raise PluginError("%s: couldn't get wheel hinge joint: %s" % (o.where, exc))
        self.every = Every(o.number('updateRate', 100.0), lambda: self.engine.time)
        source = o.text('odometrySource', 'world').lower()
        if source not in ODOMETRY_SOURCES:    # Gazebo warns and uses world, as here
            self.engine.log.warn('%s: odometrySource %r is not world or encoder; using world'
                                 % (o.where, source))
            source = 'world'
        self.encoder = None
        if source == 'encoder':
            if not self.drive.half:     # Gazebo's odometry would divide by it
                raise PluginError('%s: <wheelSeparation> 0 with odometrySource encoder'
                                  % o.where)
            self.encoder = EncoderOdometry(self.drive.radius, 2.0 * self.drive.half,
                                           self.drive.swapped,
                                           release.encoder_twist_in_child_frame)
        self._grip()

    def _grip(self):
        """The wheels grip; everything else that touches the ground (a caster) slides."""
        wheels = {self.model.urdf.joints[j].child for j in self.drive.joints}
        for link in self.model.body.links:
            self.model.set_friction(link, 1.0 if link in wheels else 0.0,
                                    spinning=0.001 if link in wheels else 0.0)

    def facts(self):
        return dict(DriveCore.facts(self), legacy_mode=self.drive.swapped)

    def before_step(self):
        # as Gazebo's UpdateChild: encoders every step; at the update rate,
        # report, then set the wheels
        if self.encoder is not None:
            _, _, rates, _ = self.model.joint_states(self.drive.joints)
            self.encoder.step(rates[0], rates[1], self.engine.time_step)
        if self.every.due():
            self.on_update()
            self.drive.apply(max(self.every.period, self.engine.time_step))

    def on_update(self):
        """At the update rate, before the wheels are set (the ROS plugin publishes)."""

    def reset(self):
        self.command.reset()
        self.every.reset()
        self.drive.reset()
        if self.encoder is not None:
            self.encoder.reset()


class SkidSteerDriveCore(DiffDriveCore):
    """``libgazebo_ros_skid_steer_drive.so`` without ROS: leftFrontJoint,
    rightFrontJoint, leftRearJoint, rightRearJoint, wheelSeparation (0.4),
    wheelDiameter (0.15), torque (5), updateRate (100), as in every release;
    no legacy mode, no encoder odometry, no wheel acceleration."""

    FILENAMES = ('libgazebo_ros_skid_steer_drive.so',)
    SIDES = (('leftFrontJoint', 'left_front_joint'), ('rightFrontJoint', 'right_front_joint'),
             ('leftRearJoint', 'left_rear_joint'), ('rightRearJoint', 'right_rear_joint'))

    def load(self):
        o = self.options
        self.command = velocity_command(self)
        names = [o.text(tag, default) for tag, default in self.SIDES]
        for (tag, _), name in zip(self.SIDES, names):
            if not self.model.has_joint(name):      # Gazebo: gzthrow, the plugin does not run
                raise PluginError('%s: GazeboRosSkidSteerDrive Plugin couldn\'t get %s hinge '
                                  'joint named "%s"' % (o.where, ' '.join(
                                      re.findall('[a-z]+|[A-Z][a-z]+', tag)[:2]).lower(), name))
        self.drive = SkidSteer(self.model, names[0::2], names[1::2],
                               o.number('wheelSeparation', 0.4),
                               o.number('wheelDiameter', 0.15, nonzero=True),
                               o.number('torque', 5.0, minimum=0.0), self.command)
        self.every = Every(o.number('updateRate', 100.0), lambda: self.engine.time)
        self.encoder = None
        self._grip()

    def facts(self):
        return DriveCore.facts(self)


class PlanarMoveCore(DriveCore):
    """``libgazebo_ros_planar_move.so`` without ROS: the command is in the
    body's frame (x, y, yaw rate), applied every step; it holds until another
    comes, or for ``cmdTimeout`` s where the release reads it (Noetic, 2.9.2:
    a negative one, the default, holds for ever)."""

    FILENAMES = ('libgazebo_ros_planar_move.so',)

    def load(self):
        timeout = None
        if self.engine.release.reads_cmd_timeout and self.options.has('cmdTimeout'):
            given = self.options.number('cmdTimeout', -1.0)
            # Gazebo drops a command older than it: 0 drops it at the next step
            timeout = 0.0 if given < 0 else max(given, 1e-9)
        self.command = velocity_command(self, timeout)
        self.drive = PlanarMove(self.model, self.command, self.engine.bounds,
                                self.engine.time_step)
        if not self.model.kinematic:
            self.model.set_friction(self.model.base_frame, 0.0)

    def before_step(self):
        self.drive.apply()

    def reset(self):
        self.command.reset()


CORES = {name: cls for cls in (DiffDriveCore, SkidSteerDriveCore, PlanarMoveCore)
         for name in cls.FILENAMES}

"""What Gazebo's ROS plugins did in each ROS 1 release the course's students
used (no ROS): one table, read by the plugins.

Students wrote for ROS Kinetic (Gazebo 7, gazebo_ros_pkgs 2.5.x), Melodic
(Gazebo 9, 2.8.x) or Noetic (Gazebo 11, 2.9.x), and their code steers by
what their release's plugins did. Each :class:`Release` row holds the facts
that changed between those releases and that a student's node can see
(each with the gazebo_ros_pkgs pull request that changed it; the last
release of each is the one simulated):

* the diff drive's ``legacyMode`` (#707, Melodic 2.8.3 "End of legacy for
  diff drive plugin"): Kinetic honours it, true when the tag is absent or
  not ``true``/``false`` (with an error or warning line), and swaps the wheels: the ``leftJoint`` turns at
  (v + w s/2) / r, the ``rightJoint`` at (v - w s/2) / r, and its encoder
  odometry turns by (left - right) / s to match; Melodic and Noetic do not
  read the tag;
* the diff drive's encoder odometry twist (#719, Melodic 2.8.3): Kinetic
  publishes the odometry frame's dx/dt and dy/dt as ``linear.x`` and
  ``linear.y``; Melodic and Noetic the forward speed in the child frame;
* the TF prefix of the diff drive's frames and the camera's ``frame_id``
  (#1143, #1173, Noetic 2.9.2): Kinetic and Melodic prefix them with the
  robot namespace (``robot/odom``, ``robot/link_chassis``); Noetic does not;
* gazebo_ros_control's ``legacyModeNS`` (#637 in Kinetic, removed by #709 in
  Melodic 2.8.3): where DefaultRobotHWSim reads Gazebo's joint PID gains,
  ``/gazebo_ros_control/pid_gains/<joint>`` (Kinetic's legacy, the default
  with an error line) or ``/<ns>/gazebo_ros_control/pid_gains/<joint>``;
* planar_move's ``cmdTimeout`` (#1133, Noetic 2.9.2): read by Noetic only (a
  command older than it is dropped; -1, the default, keeps it for ever);
  Kinetic and Melodic keep the last command for ever. The diff drive and
  the skid steer drive keep it for ever in every release, and read their
  ``wheelAcceleration`` / ``wheelTorque`` / ``updateRate`` alike in all three.

The release is chosen by the simulator's ``~ros_release`` parameter, else the
environment's :data:`ENV`, else :data:`DEFAULT` (:func:`choose`).
"""
from collections import OrderedDict, namedtuple

from exp_assignment2.sim import node_setting

ENV = 'EXP2_ROS_RELEASE'
DEFAULT = 'noetic'


class ReleaseError(ValueError):
    """An unknown release: the message is the whole line, naming the known ones."""


class Release(namedtuple('Release', 'name gazebo gazebo_ros_pkgs legacy_mode legacy_mode_ns '
                                    'encoder_twist_in_child_frame prefix_frames_with_namespace '
                                    'booleans reads_cmd_timeout')):
    """One ROS release's Gazebo plugins. ``legacy_mode`` and ``legacy_mode_ns``
    are the tag's default when it is read, None when the release ignores it;
    ``booleans``: the words gazebo_ros' getParameterBoolean takes (2.8.4 added 1 and 0);
    ``reads_cmd_timeout``: planar_move reads ``cmdTimeout``."""

    @property
    def reads_legacy_mode(self):
        return self.legacy_mode is not None

    @property
    def reads_legacy_mode_ns(self):
        return self.legacy_mode_ns is not None

    def boolean(self, text, default):
        """(value, understood) of a tag read as gazebo_ros' getParameterBoolean
        reads it: absent (None or '') or not one of :attr:`booleans` (which it
        warns about) leaves ``default``."""
        if text is None or str(text).strip() == '':
            return default, True
        word = str(text).strip().lower()
        if word not in self.booleans:
            return default, False
        return word in ('true', '1'), True

    def swaps_wheels(self, legacy_mode):
        """Whether the diff drive turns ``leftJoint`` at v + w s/2 (Kinetic's
        legacy mode); ``legacy_mode`` is the tag's value, None when absent."""
        if not self.reads_legacy_mode:
            return False
        return self.legacy_mode if legacy_mode is None else bool(legacy_mode)

    def pid_gains_namespace(self, robot_namespace, legacy_mode_ns):
        """Where gazebo_ros_control's DefaultRobotHWSim reads a joint's PID
        gains (``<this>/<joint>/p``...); ``legacy_mode_ns``: the tag's value,
        None when absent. The controllers' own parameters are read under the
        robot namespace in every release."""
        legacy = self.reads_legacy_mode_ns and (
            self.legacy_mode_ns if legacy_mode_ns is None else bool(legacy_mode_ns))
        ns = '' if legacy else robot_namespace.strip('/')
        return '/%s/gazebo_ros_control/pid_gains' % ns if ns else '/gazebo_ros_control/pid_gains'

    def frame(self, name, robot_namespace):
        """A plugin's frame as it publishes it: tf's ``resolve`` of ``name``
        with the robot namespace as prefix where the release makes it one."""
        prefix = robot_namespace.strip('/') if self.prefix_frames_with_namespace else ''
        return tf_resolve(prefix, name)

    def describe(self):
        return '%s (Gazebo %s, gazebo_ros_pkgs %s)' % (self.name, self.gazebo,
                                                       self.gazebo_ros_pkgs)


RELEASES = OrderedDict((r.name, r) for r in (
    Release('kinetic', '7', '2.5', legacy_mode=True, legacy_mode_ns=True,
            encoder_twist_in_child_frame=False, prefix_frames_with_namespace=True,
            booleans=('true', 'false'), reads_cmd_timeout=False),
    Release('melodic', '9', '2.8', legacy_mode=None, legacy_mode_ns=None,
            encoder_twist_in_child_frame=True, prefix_frames_with_namespace=True,
            booleans=('true', 'false', '1', '0'), reads_cmd_timeout=False),
    Release('noetic', '11', '2.9', legacy_mode=None, legacy_mode_ns=None,
            encoder_twist_in_child_frame=True, prefix_frames_with_namespace=False,
            booleans=('true', 'false', '1', '0'), reads_cmd_timeout=True),
))


def tf_resolve(prefix, name):
    """tf's ``resolve(prefix, name)``: an absolute name loses its slash, a
    relative one gets ``prefix/`` when there is a prefix."""
    if name.startswith('/'):
        return name.lstrip('/')
    prefix = prefix.strip('/')
    return '%s/%s' % (prefix, name) if prefix else name


def release(name=None):
    """The :class:`Release` called ``name`` (None or '': :data:`DEFAULT`);
    :class:`ReleaseError` for another name."""
    if name is None or (isinstance(name, str) and not name.strip()):
        return RELEASES[DEFAULT]
    key = name.strip().lower() if isinstance(name, str) else name
    if key not in RELEASES:
        raise ReleaseError('ROS release %r is refused; accepted: %s (gazebo_ros_pkgs %s)'
                           % (name, ', '.join(RELEASES),
                              ', '.join(r.gazebo_ros_pkgs for r in RELEASES.values())))
    return RELEASES[key]


def choose(parameter=None, environ=None):
    """The release a simulator runs as: its ``~ros_release`` parameter when
    given, else ``environ[ENV]`` (the grader sets it in a run's sandbox),
    else :data:`DEFAULT`. :class:`ReleaseError` names a bad value and where
    it came from."""
    return node_setting.chosen(parameter, '~ros_release', ENV, release, environ)

"""gazebo_ros' ``spawn_model`` command line, read without ROS.

``spawn_model -urdf|-sdf -param P|-file F|-database NAME|-stdin -model NAME
[-x X -y Y -z Z -R R -P P -Y Y] [-J JOINT VALUE]... [-reference_frame F]
[-robot_namespace NS] [-gazebo_namespace NS] [-unpause] [-wait MODEL]
[-timeout S] [-package_to_model] [-b]``, as Gazebo's: an option given twice
takes its last value (Kinetic's loop and Melodic's argparse alike); an
argument spawn_model does not know is ignored as Kinetic's ignored it, and
refused as Melodic's and Noetic's argparse refuses it (``release``); two
formats or two sources are refused in every release. ``-timeout`` is this
package's own. Numbers must be finite (a NaN pose would break the world).
Also the pose's quaternion and the model XML helpers the node needs.
"""
import math
import xml.etree.ElementTree as ET
from collections import namedtuple

DEFAULT_TIMEOUT = 60.0      # s of wall time to wait for the simulator's services
FORMATS = ('-urdf', '-sdf')
SOURCES = ('-file', '-param', '-database', '-stdin')
FLAGS = ('-unpause', '-package_to_model', '-b')
TEXT_OPTIONS = ('-model', '-reference_frame', '-gazebo_namespace', '-robot_namespace', '-wait')
NUMBER_OPTIONS = ('-x', '-y', '-z', '-R', '-P', '-Y', '-timeout')
USAGE = ('usage: spawn_model -urdf|-sdf -file FILE|-param PARAM|-database NAME|-stdin '
         '-model NAME [-x X] [-y Y] [-z Z] [-R ROLL] [-P PITCH] [-Y YAW] '
         '[-J JOINT POSITION]... [-reference_frame FRAME] [-robot_namespace NS] '
         '[-gazebo_namespace NS] [-unpause] [-wait MODEL] [-timeout S] [-package_to_model] [-b]')
DATABASE_TEMPLATE = ('<sdf version="1.4"><world name="default"><include><uri>model://%s</uri>'
                     '</include></world></sdf>')

SpawnOptions = namedtuple('SpawnOptions', 'format source source_value model pose joints '
                          'reference_frame robot_namespace gazebo_namespace unpause wait '
                          'timeout package_to_model bond ignored')
SpawnOptions.__doc__ = """A spawn_model command line: format ('urdf' or 'sdf'),
source ('file', 'param', 'database', 'stdin') and its value, model name,
pose (x, y, z, roll, pitch, yaw), joints [(name, position)], reference
frame, robot namespace (None: the node's), Gazebo's namespace, unpause, wait
(a model name or None), timeout (s), package_to_model, bond, and the arguments ignored (Kinetic's)."""


class UsageError(ValueError):
    """A command line spawn_model refuses; the message says why and what is accepted."""


def parse(argv, release='noetic'):
    """Read spawn_model's arguments (ROS remappings already removed) as the
    spawn_model of ``release`` (a ROS release's name) reads them."""
    given = {}      # what -> (option, value); what: format, source, or the option itself
    pose, joints, ignored = {}, [], []
    args = list(argv)
    while args:
        arg = args.pop(0)
        if arg in FORMATS:
            _once(given, 'format', arg, arg[1:])
        elif arg in SOURCES:
            _once(given, 'source', arg, None if arg == '-stdin' else _text(args, arg))
        elif arg in FLAGS:
            given[arg] = (arg, True)
        elif arg in TEXT_OPTIONS:
            given[arg] = (arg, _text(args, arg))
        elif arg in NUMBER_OPTIONS:
            value = _number(arg, _text(args, arg))
            if arg == '-timeout' and value <= 0:
                raise UsageError('spawn_model: -timeout must be positive, not %g' % value)
            (given if arg == '-timeout' else pose)[arg] = (arg, value)
        elif arg == '-J':
            name = _text(args, arg)
            joints.append((name, _number('-J %s' % name, _text(args, '-J ' + name))))
        elif release == 'kinetic':      # its loop looks for what it knows, and no more
            ignored.append(arg)
        else:
            raise UsageError('spawn_model: unknown argument %r (spawn_model of ROS %s refuses it: '
                             'unrecognized arguments)\n%s' % (arg, release, USAGE))
    for what, needed in (('format', '-urdf or -sdf'),
                         ('source', '-file, -param, -database or -stdin'),
                         ('-model', '-model NAME')):
        if what not in given:
            raise UsageError('spawn_model: %s is required\n%s' % (needed, USAGE))

    def value(what, default=None):
        return given[what][1] if what in given else default
    return SpawnOptions(
        value('format'), given['source'][0][1:], value('source'), value('-model'),
        tuple(pose[k][1] if k in pose else 0.0 for k in ('-x', '-y', '-z', '-R', '-P', '-Y')),
        joints, value('-reference_frame', ''), value('-robot_namespace'),
        value('-gazebo_namespace', '/gazebo').rstrip('/') or '/gazebo',
        value('-unpause', False), value('-wait'), value('-timeout', DEFAULT_TIMEOUT),
        value('-package_to_model', False), value('-b', False), ignored)


def _once(given, what, option, value):
    """A format or a source: the same one again takes the last value; two
    different ones are refused, as every release's spawn_model refuses them."""
    if what in given and given[what][0] != option:
        raise UsageError('spawn_model: %s and %s cannot both be given'
                         % (given[what][0], option))
    given[what] = (option, value)


def _text(args, option):
    if not args:
        raise UsageError('spawn_model: %s needs a value\n%s' % (option, USAGE))
    return args.pop(0)


def _number(option, text):
    try:
        value = float(text)
    except ValueError:
        value = float('nan')
    if not math.isfinite(value):
        raise UsageError('spawn_model: %s must be a finite number, not %r' % (option, text))
    return value


def quaternion(roll, pitch, yaw):
    """(x, y, z, w) of fixed-axis roll, pitch, yaw (tf's quaternion_from_euler)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def database_xml(name):
    """What Gazebo's ``-database NAME`` sends: a world including model://NAME."""
    return DATABASE_TEMPLATE % name


def checked_xml(text, package_to_model=False):
    """The model XML, checked to be XML (ValueError with the parser's reason);
    with ``package_to_model``, mesh ``package://`` URLs become ``model://``."""
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise ValueError('Invalid XML: %s' % exc)
    if not package_to_model:
        return text
    for mesh in root.iter('mesh'):
        filename = mesh.get('filename', '')
        if filename.startswith('package://'):
            mesh.set('filename', 'model://' + filename[len('package://'):])
    return ET.tostring(root, encoding='unicode')

"""gazebo_ros' ``gzserver`` (and ``debug``): Gazebo's server command line
turned into this package's simulator's (no rospy here).

A launch file runs ``gzserver [-u] [-r] [--verbose] -e ode [extra args]
WORLD __name:=gazebo __log:=...``. :func:`translate` reads that as Gazebo's
Server::ParseArgs does: ``-u`` starts paused, the first other word is the
world file, resolved as Gazebo resolves it (a path, or a name on
``GAZEBO_RESOURCE_PATH``; ``worlds/empty.world`` is the empty world), and the
words after it are passed through to system plugins (ignored); options the
simulator has no use for are accepted with one line saying so, and so are
options Gazebo does not know (its parser allows unregistered ones). A world
that cannot be found, an unknown physics engine and a missing value are
refused, as gzserver exits on them. ROS arguments (``name:=value``) pass
through, so the node is named as the launch file says. :func:`main` then
replaces this process with ``/usr/bin/python3 scripts/simulator.py`` given
``_world_file``, ``_paused`` and ``_cmd_timeout:=0``: Gazebo's drive plugins
keep the last velocity command until another comes.
"""
import json
import os
import sys
from collections import namedtuple

from exp_assignment2.layout import SCRIPTS

PYTHON = '/usr/bin/python3'
ENGINES = ('ode', 'bullet', 'simbody', 'dart')
EMPTY_WORLDS = ('worlds/empty.world', 'empty.world')
API_PLUGINS = ('libgazebo_ros_api_plugin.so', 'libgazebo_ros_paths_plugin.so')
# options that take a value and are accepted but change nothing here, and why
IGNORED_WITH_VALUE = {
    '--seed': 'the simulator has no random elements to seed',
    '--iters': 'the simulator runs until it is stopped',
    '--record_path': 'runs are not recorded (use rosbag)',
    '--record_period': 'runs are not recorded (use rosbag)',
    '--record_filter': 'runs are not recorded (use rosbag)',
    '--record_encoding': 'runs are not recorded (use rosbag)',
    '-o': 'physics profiles are not read', '--profile': 'physics profiles are not read',
}
IGNORED_FLAGS = {
    '-r': 'runs are not recorded (use rosbag)', '--record': 'runs are not recorded (use rosbag)',
    '--verbose': None, '-q': None, '--quiet': None, '--lockstep': None,
    '--minimal_comms': None, '--record_resources': 'runs are not recorded (use rosbag)',
}
USAGE = ('usage: gzserver [-u|--pause] [-e|--physics ode|bullet|simbody|dart] [--verbose] '
         '[-r] [-s PLUGIN] [--seed N] [--iters N] [-o PROFILE] [WORLD_FILE] [ROS args]')

ServerCommand = namedtuple('ServerCommand', 'world paused verbose notes ros_args')
ServerCommand.__doc__ = """What a gzserver command line asks for: the world file
(None: the empty world), paused, verbose, lines about what is ignored, and the
ROS arguments to pass on."""


class UsageError(ValueError):
    """A gzserver command line that cannot be run; the message says why."""


def translate(argv, environ=None):
    """Read gzserver's arguments (without the program name)."""
    environ = os.environ if environ is None else environ
    paused = verbose = False
    notes, ros_args, worlds = [], [], []
    args = list(argv)
    while args:
        arg = args.pop(0)
        option, _, inline = arg.partition('=') if arg.startswith('--') else (arg, '', '')
        if ':=' in arg:
            ros_args.append(arg)
        elif arg in ('-u', '--pause'):
            paused = True
        elif option in ('-e', '--physics'):
            engine = inline or _value(args, option)
            if engine not in ENGINES:
                raise UsageError('gzserver: unknown physics engine %r; accepted: %s'
                                 % (engine, ', '.join(ENGINES)))
        elif option in ('-s', '--server-plugin'):
            plugin = inline or _value(args, option)
            if os.path.basename(plugin) not in API_PLUGINS:
                notes.append('gzserver: server plugin %s is not available here: ignored'
                             % plugin)
        elif option in IGNORED_WITH_VALUE:
            notes.append('gzserver: %s %s ignored: %s' % (
                option, inline or _value(args, option), IGNORED_WITH_VALUE[option]))
        elif arg in IGNORED_FLAGS:
            verbose = verbose or arg == '--verbose'
            if IGNORED_FLAGS[arg]:
                notes.append('gzserver: %s ignored: %s' % (arg, IGNORED_FLAGS[arg]))
        elif option in ('-p', '--play'):
            raise UsageError('gzserver: %s (playing a Gazebo log) is not supported; '
                             'replay a rosbag instead' % option)
        elif arg.startswith('-') and arg != '-':
            notes.append('gzserver: unknown option %r ignored (as Gazebo ignores options it '
                         'does not know)' % arg)
        else:
            worlds.append(arg)
    if len(worlds) > 1:         # Gazebo's "pass_through" words, for system plugins
        notes.append('gzserver: %s after the world file ignored (Gazebo passes them '
                     'through to system plugins)' % ' '.join(worlds[1:]))
    world = resolve_world(worlds[0], environ) if worlds else None
    return ServerCommand(world, paused, verbose, notes, ros_args)


def _value(args, option):
    if not args or (args[0].startswith('-') and len(args[0]) > 1):
        raise UsageError('gzserver: %s needs a value\n%s' % (option, USAGE))
    return args.pop(0)


def resolve_world(name, environ):
    """The world file's absolute path, None for Gazebo's empty world, as
    Gazebo finds it: the path itself, else under GAZEBO_RESOURCE_PATH."""
    if os.path.isfile(name):
        return os.path.abspath(name)
    if name in EMPTY_WORLDS:
        return None
    roots = [r for r in environ.get('GAZEBO_RESOURCE_PATH', '').split(os.pathsep) if r]
    for root in roots:
        path = os.path.join(root, name)
        if os.path.isfile(path):
            return os.path.abspath(path)
    raise UsageError('gzserver: world file %r not found (nor under GAZEBO_RESOURCE_PATH=%r); '
                     'give a path, or worlds/empty.world for the empty world'
                     % (name, environ.get('GAZEBO_RESOURCE_PATH', '')))


def simulator_argv(command, scripts=SCRIPTS):
    """The simulator's command line for a :class:`ServerCommand` (``scripts``:
    the folder of this package's executables, in its source tree or installed)."""
    # Gazebo's diff drive, skid steer and planar move hold the last command:
    # no hold of the package's own (a launch file's own _cmd_timeout still wins)
    argv = [PYTHON, os.path.join(scripts, 'simulator.py'), '_cmd_timeout:=0']
    argv += list(command.ros_args)
    # the value is read as YAML: a JSON string is a YAML string, whatever the path holds
    argv.append('_world_file:=%s' % json.dumps(command.world or ''))
    if command.paused:
        argv.append('_paused:=true')
    return argv


def main(argv=None, program='gzserver'):
    """Run the simulator in place of this process, as Gazebo's server."""
    argv = sys.argv[1:] if argv is None else argv
    if '-h' in argv or '--help' in argv:
        print(USAGE)
        return 0
    try:
        command = translate(argv)
    except UsageError as exc:
        print(str(exc), file=sys.stderr)
        return 2
    for note in command.notes:
        print(note, flush=True)
    if program == 'debug':
        print('debug: no debugger is attached here; running gzserver', flush=True)
    if command.verbose:
        print('gzserver: %s%s, on exp_assignment2\'s simulator' % (
            command.world or 'the empty world', ', paused' if command.paused else ''),
            flush=True)
    argv = simulator_argv(command)
    os.execv(argv[0], argv)

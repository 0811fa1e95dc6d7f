"""controller_manager's ``spawner`` command line, read without ROS.

``spawner [--namespace NS] [--stopped] [--wait-for TOPIC] [--timeout S |
--no-timeout] [--shutdown-timeout S] CONTROLLER...``, options anywhere, as
``--option=value`` too and shortened to any unique prefix (``--ns``,
``--stop``), as the real spawner's argparse reads them. Anything else is
refused with a line that says what is accepted, as argparse refuses it.
"""
import math
from collections import namedtuple

USAGE = ('usage: spawner [--namespace NS] [--stopped] [--wait-for TOPIC] [--timeout S | '
         '--no-timeout] [--shutdown-timeout S] CONTROLLER [CONTROLLER ...]')
DEFAULT_TIMEOUT, DEFAULT_SHUTDOWN_TIMEOUT = 30.0, 2.0     # s, the real spawner's

SpawnerOptions = namedtuple('SpawnerOptions', 'controllers namespace stopped wait_for timeout '
                            'shutdown_timeout')
SpawnerOptions.__doc__ = """A spawner command line: the controllers, the
namespace of the controller manager ('' : the node's), stopped (load only),
the Bool topic to wait for (or None), the service timeout (None: no
timeout) and the shutdown timeout, in s."""


class UsageError(ValueError):
    """A command line the spawner refuses; the message says why and what is accepted."""


def parse(argv):
    """Read the spawner's arguments (ROS remappings already removed)."""
    controllers, given = [], {}
    args = list(argv)
    while args:
        arg = args.pop(0)
        option, equals, inline = arg.partition('=')
        option = _unabbreviated(option)
        if option in ('--stopped', '--no-timeout'):
            if equals:
                raise UsageError('spawner: %s takes no value\n%s' % (option, USAGE))
            given[option] = True
        elif option in ('--namespace', '--wait-for', '--timeout', '--shutdown-timeout'):
            if not equals:
                if not args:
                    raise UsageError('spawner: %s needs a value\n%s' % (option, USAGE))
                inline = args.pop(0)
            given[option] = inline
        elif arg.startswith('-'):
            raise UsageError('spawner: unknown option %r\n%s' % (arg, USAGE))
        else:
            controllers.append(arg)
    if not controllers:
        raise UsageError('spawner: name at least one controller\n%s' % USAGE)
    timeout = None if given.get('--no-timeout') else _seconds(
        '--timeout', given.get('--timeout'), DEFAULT_TIMEOUT)
    return SpawnerOptions(controllers, given.get('--namespace', ''), bool(
        given.get('--stopped')), given.get('--wait-for'), timeout, _seconds(
        '--shutdown-timeout', given.get('--shutdown-timeout'), DEFAULT_SHUTDOWN_TIMEOUT))


OPTIONS = ('--stopped', '--no-timeout', '--namespace', '--wait-for', '--timeout',
           '--shutdown-timeout')


def _unabbreviated(option):
    """argparse's reading of a long option's unique prefix (``--ns``: none,
    ``--name``: --namespace); ambiguous or unknown ones stay as given."""
    if not option.startswith('--') or option in OPTIONS:
        return option
    matches = [o for o in OPTIONS if o.startswith(option)]
    return matches[0] if len(matches) == 1 else option


def _seconds(option, text, default):
    if text is None:
        return default
    try:
        value = float(text)
    except ValueError:
        value = float('nan')
    if not math.isfinite(value) or value <= 0:
        raise UsageError('spawner: %s must be a positive number of seconds, not %r'
                         % (option, text))
    return value


def manager_namespace(namespace, node_namespace):
    """The controller manager's namespace (where its services and the
    controllers' parameters are): ``--namespace`` resolved against the node's
    namespace, or the node's namespace itself."""
    base = node_namespace if node_namespace.endswith('/') else node_namespace + '/'
    if not namespace:
        resolved = base
    elif namespace.startswith('/'):
        resolved = namespace
    else:
        resolved = base + namespace
    parts = [p for p in resolved.split('/') if p]
    return '/' + '/'.join(parts)


def service_names(namespace):
    """load, switch and unload services of the controller manager in ``namespace``."""
    root = namespace.rstrip('/') + '/controller_manager/'
    return tuple(root + s for s in ('load_controller', 'switch_controller', 'unload_controller'))

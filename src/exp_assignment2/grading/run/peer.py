"""Which program is at the other end of the ground truth's socket (no ROS).

The grader takes the ground truth from this package's simulator only, and
only once per run. The simulator reaches the socket however the student's
launch files start it, and each way names its script differently on the
process's command line:

* the source tree: ``python3 REPO/scripts/simulator.py`` (the ``gazebo_ros``
  stand-ins' ``gzserver`` execs this; ``exp_assignment2_sim``, the second
  name of this package, links to ``REPO/scripts``);
* catkin's devel space: ``devel/lib/exp_assignment2/simulator.py``, a relay
  generated from catkin's ``script.py.in`` that executes the source file
  (what ``roslaunch exp_assignment2 miro_world.launch`` starts in a
  workspace);
* catkin's install space: ``install/lib/exp_assignment2/simulator.py``, a
  copy of the source whose first line (the interpreter) was rewritten.

Each is accepted only when what the file would run is the repository's
simulator, the file is one the run cannot write (a file in the run's own
directory could be changed between the process's start and this look), and
the process is Debian's Python running that file as its script.
"""
import os
import re
import socket
import struct

from exp_assignment2.grading.paths import SIMULATOR

# catkin's relay (catkin/cmake/templates/script.py.in), with its two fields
RELAY = re.compile(
    r"\A#!(?P<python>\S+)\n"
    r"# -\*- coding: utf-8 -\*-\n"
    r"# generated from catkin/cmake/template/script\.py\.in\n"
    r"# creates a relay to a python script source file, acting as that file\.\n"
    r"# The purpose is that of a symlink\n"
    r"python_script = '(?P<script>[^'\n]+)'\n"
    r"with open\(python_script, 'r'\) as fh:\n"
    r"    context = \{\n"
    r"        '__builtins__': __builtins__,\n"
    r"        '__doc__': None,\n"
    r"        '__file__': python_script,\n"
    r"        '__name__': __name__,\n"
    r"        '__package__': None,\n"
    r"    \}\n"
    r"    exec\(compile\(fh\.read\(\), python_script, 'exec'\), context\)\n?\Z")
# Python's options that take the next word (python3 -X dev script.py)
_OPTION_WITH_VALUE = ('-X', '-W')
# options after which there is no script file: the code comes from elsewhere
_NO_SCRIPT = ('-c', '-m', '-')
READ_LIMIT = 1 << 20


def peer_process(conn):
    """(pid, argv, executable) of the process at the other end of a Unix socket."""
    creds = conn.getsockopt(socket.SOL_SOCKET, socket.SO_PEERCRED, struct.calcsize('3i'))
    pid = struct.unpack('3i', creds)[0]
    try:
        with open('/proc/%d/cmdline' % pid, 'rb') as f:
            argv = [a.decode(errors='replace') for a in f.read().split(b'\0') if a]
    except OSError:
        argv = []
    try:
        executable = os.path.realpath('/proc/%d/exe' % pid)
    except OSError:
        executable = ''
    return pid, argv, executable


def script_of(argv):
    """The script file a ``python3 [options] SCRIPT args`` command line runs, or None."""
    if not argv or not os.path.basename(argv[0]).startswith('python'):
        return None
    words = iter(argv[1:])
    for word in words:
        if word in _NO_SCRIPT or word.startswith(('-c', '-m')) and len(word) > 2:
            return None
        if word in _OPTION_WITH_VALUE:
            next(words, None)
            continue
        if word.startswith('-'):
            continue
        return word
    return None


def _read(path):
    try:
        with open(path, 'rb') as f:
            return f.read(READ_LIMIT).decode(errors='replace')
    except OSError:
        return None


def _body(text):
    """A script without its first line (the interpreter catkin rewrites)."""
    return text.split('\n', 1)[1] if text and text.startswith('#!') and '\n' in text else text


def runs_simulator_file(path, simulator=SIMULATOR):
    """How the file ``path`` runs the repository's simulator ('source', 'relay',
    'copy'), or None when it does not."""
    real = os.path.realpath(path)
    if real == simulator:
        return 'source'
    text = _read(real)
    if text is None:
        return None
    match = RELAY.match(text)
    if match:
        return 'relay' if os.path.realpath(match.group('script')) == simulator else None
    original = _read(simulator)
    if original is not None and text != original and _body(text) == _body(original):
        return 'copy'
    return None


def runs_our_simulator(argv, may_write=None, executable=None, simulator=SIMULATOR):
    """Is this process (its command line, and its executable when known) the
    repository's simulator, started from a file the run cannot change?
    ``may_write(path)``: could the run have written that file (its sandbox says)."""
    script = script_of(argv)
    if script is None:
        return False
    if executable is not None and not os.path.basename(executable).startswith('python'):
        return False
    if may_write is not None and os.path.realpath(script) != simulator and (
            may_write(script) or may_write(os.path.realpath(script))):
        return False
    return runs_simulator_file(script, simulator) is not None

"""How roslaunch and rosrun start a node's file in the original-code shell:
as the students' machines started it.

Three things there worked that do not here:

* a script whose first line names Python 2 (``#!/usr/bin/python``,
  ``#!/usr/bin/python2``, ``#!/usr/bin/env python2``): Ubuntu had that
  interpreter (or ``python-is-python3``). Such a file is started with this
  shell's ``python`` (python_launcher.sh: /usr/bin/python3 with Python 2's tab
  rule), never by changing the file or the machine's ``/usr/bin/python``;
* a file that lost its execute bit on its way to the teacher (a zip, a
  commit from Windows): on the student's machine it was executable. It is
  started as if it were, through the interpreter its first line names
  (``python`` for a Python one, and for a ``.py`` file without one), and
  stderr says which file, once;
* a node type of an earlier ROS 1 release that Noetic dropped
  (:data:`RENAMED`, from the Noetic migration notes), such as
  ``robot_state_publisher``'s ``state_publisher``: the same program under
  Noetic's name is started, with one stderr line naming both.

:func:`command` decides for one file; :func:`install` patches
``roslaunch.node_args.create_local_process_args`` when roslaunch imports it;
src/exp_assignment2/original_env/programs/rosrun.py (``rosrun`` on this shell's PATH) uses both.
"""
import os
import re
import sys

# the names of a Python that is not Python 3: Ubuntu's python, python2, python2.7
PYTHON_NOT_3 = re.compile(r'^python(2(\.\d+)?)?$')
# (package, type) of Kinetic's and Melodic's launch files -> Noetic's type, and since when.
# xacro's xacro.py is the other such name: it is a file of the xacro stand-in
# (launch_packages.ALIASES), found by $(find xacro)/xacro.py as before.
RENAMED = {
    ('robot_state_publisher', 'state_publisher'):
        ('robot_state_publisher', 'an older name of the same program, removed in Noetic'),
}
_told = set()


def launcher():
    """This shell's ``python`` (python_launcher.sh), else /usr/bin/python3."""
    python = os.path.join(os.environ.get('EXP2_ORIGINAL_BIN', ''), 'python')
    return python if os.environ.get('EXP2_ORIGINAL_BIN') and os.access(python, os.X_OK) \
        else '/usr/bin/python3'


def shebang(path):
    """The words of a file's ``#!`` line ([] without one)."""
    try:
        with open(path, 'rb') as f:
            first = f.readline(512)
    except (IOError, OSError):
        return []
    if not first.startswith(b'#!'):
        return []
    return first[2:].decode('utf-8', 'replace').split()


def names_python_not_3(words):
    """Does a ``#!`` line name python, python2 or python2.X (directly or through env)?"""
    if not words:
        return False
    if os.path.basename(words[0]) == 'env':
        words = [w for w in words[1:] if not w.startswith('-') and '=' not in w]
    return bool(words) and bool(PYTHON_NOT_3.match(os.path.basename(words[0])))


def command(path):
    """The command that starts ``path`` as the students' machines did, or None
    when it starts as it is (or cannot start at all)."""
    words = shebang(path)
    if names_python_not_3(words):
        return [launcher(), path]
    if os.access(path, os.X_OK):
        return None
    if words:
        interpreter = [launcher()] if os.path.basename(words[-1]).startswith('python') and \
            os.path.basename(words[0]) == 'env' else words
        return interpreter + [path]
    if path.endswith('.py'):
        return [launcher(), path]
    return None


def tell_not_executable(paths):
    """One stderr line naming the files started without their execute bit (each once)."""
    new = [p for p in paths if p not in _told]
    if new:
        _told.update(new)
        sys.stderr.write('[original-env] not executable, started as if it were (the files '
                         'are not changed): %s\n' % ', '.join(new))
        sys.stderr.flush()


def renamed(package, name):
    """Noetic's type for an earlier release's (package, type), or None."""
    found = RENAMED.get((package, name))
    return found[0] if found else None


def tell_renamed(package, name):
    """One stderr line for a node type started under Noetic's name (each once)."""
    key = ('renamed', package, name)
    if key not in _told:
        _told.add(key)
        new, since = RENAMED[(package, name)]
        sys.stderr.write('[original-env] %s/%s: started as %s/%s, its name in ROS Noetic (%s; '
                         'the launch file is not changed)\n' % (package, name, package, new,
                                                                 since))
        sys.stderr.flush()


def find_file(package, name, rospack=None):
    """(path, executable) of the file ``name`` in ``package`` that rosrun and
    roslaunch would start: the executable one, else the only plain file
    of that name; (None, False) if there is none or more than one."""
    import roslib.packages
    found = [p for p in roslib.packages.find_resource(package, name, rospack=rospack)
             if os.path.isfile(p)]
    runnable = [p for p in found if os.access(p, os.X_OK)]
    if runnable:
        return runnable[0], True
    unique = sorted(set(os.path.realpath(p) for p in found))
    return (found[0], False) if len(unique) == 1 else (None, False)


def _patch_node_args(node_args):
    original = node_args.create_local_process_args
    packages = node_args.roslib.packages

    def create_local_process_args(node, machine, env=None):
        try:
            args, path = original(node, machine, env=env), None
        except node_args.NodeParamsException:
            try:
                path, _ = find_file(node.package, node.type)
            except Exception:
                path = None
            new = renamed(node.package, node.type) if path is None else None
            if new is not None:
                args = _renamed_args(original, packages, node, machine, env, new)
                if args is not None:
                    return args
            if path is None or command(path) is None:
                raise
            # roslaunch's own command line, with the file taken as it would take
            # an executable one
            find_node = packages.find_node
            packages.find_node = lambda *a, **k: [path]
            try:
                args = original(node, machine, env=env)
            finally:
                packages.find_node = find_node
            tell_not_executable([path])
        if path is None:
            matches = packages.find_node(node.package, node.type)   # as roslaunch found it
            path = matches[0] if matches else None
        start = command(path) if path in args else None
        if start is None:
            return args
        index = args.index(path)
        return args[:index] + start + args[index + 1:]

    node_args.create_local_process_args = create_local_process_args


def _renamed_args(original, packages, node, machine, env, new):
    """roslaunch's command line for ``node`` under Noetic's type ``new``, or None."""
    matches = packages.find_node(node.package, new)
    if not matches:
        return None
    find_node = packages.find_node
    packages.find_node = lambda *a, **k: matches[:1]
    try:
        args = original(node, machine, env=env)
    finally:
        packages.find_node = find_node
    tell_renamed(node.package, node.type)
    return args


def install():
    """Patch roslaunch's node command lines when (if) roslaunch imports node_args."""
    import exp2_import_patch
    exp2_import_patch.patch_on_import('roslaunch.node_args', _patch_node_args,
                                      'original-env node start')

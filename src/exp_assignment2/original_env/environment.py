"""The original-code environment: what tools/original_env/shell.sh runs a
command in, and what the grader starts each of a submission's commands with.

:func:`environment` makes it (the workspace sourced; with a package, that
package built in an overlay; the python launchers and the stand-in packages
put where they are run from) and returns it as a dict for ``subprocess``;
:func:`compute` is its last step, the variables that switch the start-up
hooks on:

* PYTHONPATH: startup/ first (sitecustomize.py: the tab rule, Python 2 code
  translated in memory, the keyboard at end-of-file, cv2 HighGUI on one
  thread, ...), then what was there, then one shim directory per module
  that does not import *now*: smach, smach_ros. Each is checked in a fresh
  interpreter with the shims decided so far (smach_ros needs a smach), so a
  real module is never shadowed; the shims also come last.
* ROS_PACKAGE_PATH: $EXP2_LAUNCH_PACKAGES (the executable copy of
  stand_in_packages/: gazebo_ros, xacro, controller_manager, image_transport for
  the user's launch files; stand_in_packages/README.md) first; EXP2_LIBRARY:
  the folder holding this Python package, where those wrappers import it from;
  EXP2_REPO: everything of this package (the repository, or the install
  space's prefix: :mod:`exp_assignment2.layout`), whose scripts start as they are.
* PATH: $EXP2_ORIGINAL_BIN (``python``, ``python2``, ``python3``:
  programs/python_launcher.sh, /usr/bin/python3 with Python 2's tab rule for a
  script, also for ``#!/usr/bin/env python`` scripts such as the original's;
  ``rosrun``: programs/rosrun.py; ``xacro``; ``gnome-terminal``, ``xterm``,
  ``konsole``, ``terminator``: programs/terminal.py) and /usr/bin before the rest.
* EXP2_ORIGINAL_ENV: the one-line summary the shell prints.

Installing Debian's and PyPI's packages is not done here: shell.sh (and
``tools/run grade``, before any sandbox) does it first.

    /usr/bin/python3 -c 'import sys; sys.path.insert(0, "REPO/src"); ...; main()' \
        [--package DIR] [--with MORE]...
prints the shell code that turns the caller's environment into it
(shell.sh evals it), or one line and status 1.
"""
import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys

from exp_assignment2 import layout
from exp_assignment2.original_env import launch_packages
from exp_assignment2.original_env.overlay.build import BuildFailed, build, log
from exp_assignment2.original_env.sourcing import sourced

HERE = os.path.dirname(os.path.realpath(__file__))
STARTUP = os.path.join(HERE, 'startup')
PROGRAMS = os.path.join(HERE, 'programs')
PYTHON = '/usr/bin/python3'
DEFAULT_WORKSPACE = os.path.join('~', '.cache', 'exp_assignment2_ws')
# module to try -> shim directory that provides it
SHIMS = (
    ('smach', os.path.join(HERE, 'shims', 'smach')),
    ('smach_ros', os.path.join(HERE, 'shims', 'smach_ros')),
)


def _join(*parts):
    return os.pathsep.join(p for p in parts if p)


def imports(module, environ):
    """Does ``import module`` work in a fresh interpreter with this environment?"""
    env = dict(environ)
    env['EXP2_CV2_GUI_THREAD'] = '0'
    proc = subprocess.run([PYTHON, '-c', 'import ' + module], env=env, cwd='/',
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return proc.returncode == 0


def compute(environ):
    """Return the variables to set for the original-code environment."""
    base = environ.get('PYTHONPATH', '')
    shims, notes = [], []
    for module, directory in SHIMS:
        trial = dict(environ, PYTHONPATH=_join(base, *shims))
        name = module.split('.')[0]
        if imports(module, trial):
            notes.append('%s: installed one' % name)
        else:
            shims.append(directory)
            notes.append('%s: shim' % name)
    if environ.get('EXP2_TAB_RULE', '1') == '0':
        notes.append("tabs: Python 3's rule (EXP2_TAB_RULE=0)")
    else:
        notes.append("tabs: Python 2's rule where Python 3 refuses")
    notes.append('Python 2: ' + ('as Python 3 (EXP2_PY2=0)' if environ.get('EXP2_PY2') == '0'
                                 else 'translated in memory'))
    notes.append('keyboard: ' + ('end-of-file (EXP2_KEYBOARD_WAIT=0)'
                                 if environ.get('EXP2_KEYBOARD_WAIT') == '0' else
                                 'waits at end-of-file, as a terminal'))
    if environ.get('EXP2_CV2_GUI_THREAD', '1') == '0':
        notes.append('cv2 GUI: unchanged (EXP2_CV2_GUI_THREAD=0)')
    elif any(environ.get(v) for v in ('DISPLAY', 'WAYLAND_DISPLAY', 'QT_QPA_PLATFORM')):
        notes.append('cv2 GUI: one HighGUI thread')
    else:
        notes.append('cv2 GUI: no DISPLAY, so cv2.imshow aborts the process as OpenCV does'
                     ' (use xvfb-run or QT_QPA_PLATFORM=offscreen)')
    # gazebo_ros, xacro, controller_manager, image_transport for the user's launch
    # files (stand_in_packages/README.md)
    notes.append('gazebo_ros, xacro, controller_manager, image_transport: stand-ins')
    return {
        'ROS_PACKAGE_PATH': _join(environ.get('EXP2_LAUNCH_PACKAGES') or
                                  launch_packages.PACKAGES,
                                  environ.get('ROS_PACKAGE_PATH', '')),
        'EXP2_REPO': layout.ROOT,
        'EXP2_LIBRARY': layout.LIBRARY,
        'PYTHONPATH': _join(STARTUP, base, *shims),
        'PATH': _join(environ.get('EXP2_ORIGINAL_BIN', ''), '/usr/bin', '/bin',
                      environ.get('PATH', '')),
        'EXP2_ORIGINAL_ENV': '; '.join(notes),
    }


class NoWorkspace(Exception):
    """There is no catkin workspace to source: the one line to print."""


def environment(package_dir=None, more=(), workspace=None, environ=None, bin_dir=None,
                overlay_root=None):
    """The original-code environment (a dict) for ``package_dir`` (the user's
    catkin package, or None) with the ``more`` packages beside it (``--with``).

    ``workspace``: the catkin workspace (default ``$EXP2_WS``, else
    ~/.cache/exp_assignment2_ws) whose devel space is sourced; from an install
    space, that install space is sourced and the workspace only holds this
    environment's own files (:func:`exp_assignment2.layout.underlay_setup`);
    ``bin_dir``: where the programs first on PATH
    are written (default WORKSPACE/original_env_bin); ``overlay_root``: where
    the overlay is built (default ``$EXP2_OVERLAY_ROOT``, else
    WORKSPACE/overlays). Raises :class:`NoWorkspace` or
    :class:`~exp_assignment2.original_env.overlay.build.BuildFailed`, each
    with one line to print. Progress goes to stderr.
    """
    environ = dict(os.environ if environ is None else environ)
    if not package_dir and more:        # --with alone: the first as --package
        package_dir, more = more[0], more[1:]
    workspace = os.path.expanduser(workspace or environ.get('EXP2_WS') or DEFAULT_WORKSPACE)
    # ROS runs on Debian's python3, whatever python3 comes first on PATH.
    first = '/usr/bin:/bin:/usr/sbin:/sbin'
    if not (environ.get('PATH', '') + ':').startswith(first + ':'):
        environ['PATH'] = _join(first, environ.get('PATH', ''))
    setup = layout.underlay_setup(workspace)
    if not os.path.isfile(setup):
        raise NoWorkspace('no catkin workspace at %s: build it first with: bash tools/run setup'
                          % workspace)
    env = sourced(setup, environ)
    env.setdefault('ROS_HOME', os.path.join(workspace, 'ros_home'))
    if package_dir:
        env = build(package_dir, more, workspace, overlay_root, env)
    env['EXP2_ORIGINAL_BIN'] = bin_dir = bin_dir or os.path.join(workspace, 'original_env_bin')
    env['EXP2_LAUNCH_PACKAGES'] = launch_packages.install(workspace, environ=env)
    write_programs(bin_dir, env['EXP2_LAUNCH_PACKAGES'])
    # Decided now, with the real interpreter and the workspace's PYTHONPATH, so a
    # real smach (or smach_ros) is never shadowed.
    env.update(compute(env))
    return env


def prepare(workspace, environ):
    """Make what :func:`environment` reads from ``workspace`` but cannot write
    there in a grading run's sandbox (which shows the workspace read-only):
    the launch packages' copy, decided in the same environment (``environ``,
    the sandbox's, with the catkin space sourced). Nothing to do without a
    catkin space: :func:`environment` then says so."""
    setup = layout.underlay_setup(os.path.expanduser(workspace))
    if os.path.isfile(setup):
        launch_packages.install(workspace, environ=sourced(setup, environ))


# the terminals students open nodes in (launch-prefix="xterm -e", gnome-terminal in a
# start script): each a window of Debian's xterm, its output also where it would go
TERMINALS = ('gnome-terminal', 'xterm', 'konsole', 'terminator', 'x-terminal-emulator')


def write_programs(bin_dir, launch_packages_dir):
    """``python``, ``python2``, ``python3``, ``rosrun``, ``xacro`` and the
    terminals (:data:`TERMINALS`) in ``bin_dir``.

    The original's scripts start with "#!/usr/bin/env python": Debian has no
    "python", and another one later on PATH could not import Debian's rospy.
    python_launcher.sh is /usr/bin/python3 that also starts a script mixing
    tabs and spaces in its indentation with Python 2's tab rule (python2 too:
    ``#!/usr/bin/env python2`` ran on the students' machines). rosrun is ROS's,
    but a script naming Python 2 in its first line, or without its execute
    bit, starts as on the students' machines (startup/exp2_node_start.py;
    roslaunch gets the same through sitecustomize.py). Copied and renamed into
    place, so a program starting now never misses one; not linked: an
    executable file in the package would be one catkin does not install.
    ``xacro`` is the stand-in package's, as ROS's is (command="xacro ..." in a
    launch file), not PyPI's script, whose load_yaml fails under PyYAML 6.
    The terminals are programs/terminal.py: the command in an xterm window on
    the display, its output also on the opener's standard output (roslaunch's
    screen, a node's log), gnome-terminal's arguments understood.
    """
    os.makedirs(bin_dir, exist_ok=True)
    programs = [('python', 'python_launcher.sh'), ('python2', 'python_launcher.sh'),
                ('python3', 'python_launcher.sh'), ('rosrun', 'rosrun.py')]
    for name, source in programs + [(name, 'terminal.py') for name in TERMINALS]:
        scratch = os.path.join(bin_dir, '.%s.%d' % (name, os.getpid()))
        shutil.copyfile(os.path.join(PROGRAMS, source), scratch)
        os.chmod(scratch, 0o755)
        os.replace(scratch, os.path.join(bin_dir, name))
    scratch = os.path.join(bin_dir, '.xacro.%d' % os.getpid())
    if os.path.lexists(scratch):
        os.unlink(scratch)
    os.symlink(os.path.join(launch_packages_dir, 'xacro', 'xacro'), scratch)
    os.replace(scratch, os.path.join(bin_dir, 'xacro'))


def shell_code(env, before):
    """Shell lines that turn the environment ``before`` into ``env``."""
    lines = ['unset %s' % key for key in sorted(before) if key not in env and _NAME.match(key)]
    lines += ['export %s=%s' % (key, shlex.quote(value)) for key, value in sorted(env.items())
              if before.get(key) != value and _NAME.match(key)]
    return '\n'.join(lines)


_NAME = re.compile(r'^[A-Za-z_][A-Za-z0-9_]*$')


def main(argv=None):
    parser = argparse.ArgumentParser(description='The original-code environment, as shell code.')
    parser.add_argument('--package', help="the user's catkin package, built in an overlay")
    parser.add_argument('--with', dest='more', action='append', default=[], metavar='DIR',
                        help='more catkin packages to build beside it (repeatable)')
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    try:
        env = environment(args.package, args.more)
    except (NoWorkspace, BuildFailed) as exc:
        log(str(exc))
        return 1
    print(shell_code(env, dict(os.environ)))
    return 0


if __name__ == '__main__':
    sys.exit(main())

"""The nodes a submission's launch files start, by resolved name (namespace +
name, includes followed), read with roslaunch's own loader: no process started.

Launch files are the student's code: ``<param command="...">`` runs a program
and ``$(eval ...)`` evaluates Python while the file is read. So the reading
runs here in a throwaway bubblewrap sandbox (``read``): read-only ``/``, every
namespace unshared (no network, no other process visible), the teacher's
folder, the report and the home directory hidden, only the package shown
(read-only), ``--die-with-parent`` and a timeout. A sandbox was chosen over
patching the loader alone because patching must find every way a launch file
runs code (``command=``, ``$(eval)``, ``<rosparam>`` substitutions, a
``$(find)`` of a crafted package) and would break on roslaunch's next change;
the sandbox holds whatever the loader does. Inside, ``command=`` params are
also not run (their values are not needed to know the nodes, and xacro is slow).

Run as a script (``python3 launch_nodes.py < request.json``) it is the
sandbox's side: the request names the launch files (a package and a file name,
or a path, and the ``arg:=value`` words), and which package names mean which
directories (the student's package under its package.xml name and under the
name the README uses, this repository under its own); everything else is
found on ROS_PACKAGE_PATH: the stand-ins for gazebo_ros, xacro and
controller_manager, tools/stand_ins' message packages, and Debian's ROS.
It prints one JSON object: per launch file, its nodes or the error.
"""
import json
import os
import subprocess
import sys



def _stand_ins():
    """The folders of stand-in packages: the launch surface's and the
    messages' (the teacher's side only: the sandbox's side runs as a script,
    without this package on its path)."""
    from exp_assignment2.grading.paths import STAND_INS
    from exp_assignment2.original_env.launch_packages import PACKAGES
    return PACKAGES, STAND_INS
TIMEOUT = 60.0        # wall s to read one submission's launch files
SANDBOX_USER = 1000   # as a run's sandbox (grading/run/sandbox.py); not imported: the
                      # sandbox's side of this file runs with the standard library only


def provided_packages():
    """The package names a run's sandbox has besides the student's own (the
    stand-ins, this repository, Debian's ROS); read on the teacher's side, no
    student file involved."""
    names = {'exp_assignment2'}
    for folder in _stand_ins():
        names.update(n for n in os.listdir(folder)
                     if os.path.isfile(os.path.join(folder, n, 'package.xml')))
    try:
        import rospkg
        names.update(rospkg.RosPack(rospkg.get_ros_paths()).list())
    except Exception:       # no ROS here: the stand-ins and this package only
        pass
    return names


def read(request, shown=(), hidden=(), timeout=TIMEOUT):
    """{launch key: {'nodes': [...]} or {'error': why}} for ``request``
    (see the module's docstring), read in a sandbox; ``shown``: directories the
    reader may see (the student's package); ``hidden``: directories it must not."""
    if not request.get('launches'):
        return {}
    import shutil
    from exp_assignment2.grading.paths import PACKAGE, ROOT
    bwrap = shutil.which('bwrap')
    if not bwrap:
        return _all_failed(request, 'not read: bubblewrap (bwrap) is not installed')
    # a user of its own and no capability: bwrap started by root keeps root's
    # (a reader with CAP_SYS_ADMIN and CAP_MKNOD could mount the machine's disk)
    args = [bwrap, '--unshare-all', '--unshare-user', '--uid', str(SANDBOX_USER), '--gid',
            str(SANDBOX_USER), '--cap-drop', 'ALL', '--die-with-parent', '--new-session',
            '--ro-bind', '/', '/', '--dev', '/dev', '--proc', '/proc', '--tmpfs', '/tmp']
    for path in list(hidden) + [os.path.expanduser('~')]:
        if os.path.isdir(path):
            args += ['--tmpfs', path]
    for path in [ROOT] + list(shown):       # put back inside a hidden one
        if os.path.isdir(path):
            args += ['--ro-bind', path, path]
    env = {'PATH': '/usr/bin:/bin', 'HOME': '/tmp', 'ROS_HOME': '/tmp/ros', 'LANG': 'C.UTF-8',
           'ROS_PACKAGE_PATH': ':'.join(_unique(list(_stand_ins()) + [PACKAGE, '/usr/share']))}
    args += ['--chdir', '/tmp', '--clearenv']
    for key, value in sorted(env.items()):
        args += ['--setenv', key, value]
    args += ['--', '/usr/bin/python3', '-I', os.path.realpath(__file__)]
    try:
        proc = subprocess.run(args, input=json.dumps(request), stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, universal_newlines=True, timeout=timeout)
        return json.loads(proc.stdout.strip().splitlines()[-1])
    except subprocess.TimeoutExpired:
        return _all_failed(request, 'not read: the loader took over %g s' % timeout)
    except (OSError, ValueError, IndexError):
        return _all_failed(request, 'not read: the reader failed (%s)' % (
            (locals().get('proc') and proc.stderr.strip().splitlines() or ['no output'])[-1][:200]))


def _unique(paths):
    """The paths in order, each once (an install space's share/ holds this
    package and the message stand-ins both)."""
    return [p for i, p in enumerate(paths) if p not in paths[:i]]


def _all_failed(request, why):
    return {item['key']: {'error': why} for item in request['launches']}


# ---- the sandbox's side: only the standard library and ROS's own modules ----

def _find_launch(rospack, item):
    """The launch file's path: roslaunch's rule (a file of that name anywhere
    in the package), or a path given as it is."""
    if item.get('path'):
        return item['path']
    base = rospack.get_path(item['package'])
    found = []
    for root, dirs, files in os.walk(base):
        dirs.sort()
        if item['file'] in files:
            found.append(os.path.join(root, item['file']))
    if not found:
        raise IOError('%s has no %s' % (item['package'], item['file']))
    return found[0]


def _inside(request):
    import rosgraph.names
    import roslaunch.config
    import roslaunch.loader
    import roslaunch.xmlloader
    import rospkg
    packages = request.get('packages') or {}
    original = rospkg.RosPack.get_path

    def get_path(self, name):
        return packages[name] if name in packages else original(self, name)
    rospkg.RosPack.get_path = get_path
    param_value = roslaunch.loader.Loader.param_value

    def no_command(self, verbose, name, ptype, value, textfile, binfile, command):
        if command is not None:
            return ''       # not run: only the nodes matter here
        try:                # a missing textfile does not change which nodes start
            return param_value(self, verbose, name, ptype, value, textfile, binfile, command)
        except Exception:
            return ''
    roslaunch.loader.Loader.param_value = no_command
    # nor does a <rosparam> file that is missing or not YAML
    roslaunch.loader.Loader.load_rosparam = lambda *args, **kwargs: None
    rospack = rospkg.RosPack()
    out = {}
    for item in request['launches']:
        try:
            path = _find_launch(rospack, item)
            config = roslaunch.config.ROSLaunchConfig()
            roslaunch.xmlloader.XmlLoader().load(path, config, argv=['roslaunch', path] + list(
                item.get('args') or []), verbose=False)
            out[item['key']] = {'nodes': [rosgraph.names.ns_join(n.namespace or '/', n.name)
                                          for n in config.nodes if n.name]}
        except Exception as exc:        # whatever the file does wrong: one line
            line = ('%s: %s' % (type(exc).__name__, exc)).splitlines()[0]
            out[item['key']] = {'error': line[:300]}
    return out


if __name__ == '__main__':
    result = _inside(json.loads(sys.stdin.read()))
    sys.stdout.write('\n' + json.dumps(result) + '\n')

"""Put the launch-surface packages (stand_in_packages/: gazebo_ros, xacro,
controller_manager, image_transport, media_export, and rqt_image_view,
smach_viewer and urdf_tutorial where no real one is installed) where roslaunch
can run them, and
return that directory: ``install(WORKSPACE)`` ->
WORKSPACE/original_env_packages/<hash>.

roslaunch runs a node's ``type`` and a ``command=`` only if the file is
executable; in the repository these files are not (catkin_lint would want
every executable file of exp_assignment2 installed). So they are
copied into the workspace with their executable bits, ``xacro/xacro.py``
(old launch files' name) beside ``xacro/xacro``. One directory per content
hash, filled under a temporary name and renamed into place: shells that
start at the same time, or run while another one changes the files, never
see a half-made copy.
"""
import hashlib
import os
import shutil
import tempfile

HERE = os.path.dirname(os.path.realpath(__file__))
PACKAGES = os.path.join(HERE, 'stand_in_packages')
EXECUTABLES = ('gazebo_ros/scripts/gzserver', 'gazebo_ros/scripts/debug',
               'gazebo_ros/scripts/gzclient', 'gazebo_ros/scripts/spawn_model',
               'controller_manager/scripts/spawner', 'xacro/xacro',
               'image_transport/scripts/republish', 'rqt_image_view/scripts/rqt_image_view',
               'smach_viewer/scripts/smach_viewer.py')
ALIASES = {'xacro/xacro.py': 'xacro/xacro'}
# GUI tools (and urdf_tutorial's rviz configuration) a user's launch file may start or
# find: stand-ins only where ROS has none (Debian has none of them); a real one is never
# shadowed
IF_MISSING = ('rqt_image_view', 'smach_viewer', 'urdf_tutorial')


def installed(name, environ=None):
    """Is a real package ``name`` on ROS_PACKAGE_PATH (outside this folder)?"""
    import rospkg
    try:
        path = rospkg.RosPack(rospkg.get_ros_paths(
            os.environ if environ is None else environ)).get_path(name)
    except rospkg.ResourceNotFound:
        return False
    return not os.path.realpath(path).startswith(os.path.realpath(PACKAGES))


def digest(source=PACKAGES, left_out=()):
    """A hash of every file's path and content under ``source``, but ``left_out``."""
    h = hashlib.sha1(' '.join(left_out).encode())
    for root, dirs, files in os.walk(source):
        if os.path.relpath(root, source).split(os.sep)[0] in left_out:
            continue
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(root, name)
            h.update(os.path.relpath(path, source).encode() + b'\0')
            with open(path, 'rb') as f:
                h.update(f.read() + b'\0')
    return h.hexdigest()[:16]


def install(workspace, source=PACKAGES, left_out=None, environ=None):
    """The directory holding the packages, executable, made if needed
    (``environ``: the environment whose ROS_PACKAGE_PATH may hold real ones)."""
    if left_out is None:
        left_out = tuple(name for name in IF_MISSING if installed(name, environ))
    parent = os.path.join(workspace, 'original_env_packages')
    target = os.path.join(parent, digest(source, left_out))
    if os.path.isdir(target):
        return target
    os.makedirs(parent, exist_ok=True)
    scratch = tempfile.mkdtemp(prefix='.new-', dir=parent)
    try:
        made = os.path.join(scratch, 'packages')
        shutil.copytree(source, made, ignore=lambda d, names: [
            n for n in names if os.path.realpath(d) == os.path.realpath(source) and n in left_out])
        for alias, original in ALIASES.items():
            shutil.copy(os.path.join(made, original), os.path.join(made, alias))
        for path in EXECUTABLES + tuple(ALIASES):
            if path.split('/')[0] not in left_out:
                os.chmod(os.path.join(made, path), 0o755)
        try:
            os.rename(made, target)
        except OSError:
            if not os.path.isdir(target):     # not made by a shell that started with us
                raise
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return target

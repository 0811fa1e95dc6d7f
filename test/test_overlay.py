"""original-env --package DIR, with a user's package shaped like the course
template (test/fixtures/user_pkg: its own message and action, a script, a C++
node and a launch file), copied to a temporary directory and built through
``bash tools/run original-env --package DIR ...`` as a user would.

Needs the built catkin workspace (``bash tools/run setup``); skipped without.
The builds take a few minutes on two cores: one package is built once for the
module and then changed, broken and restored; a renamed copy is built once.
"""
import hashlib
import os
import shutil
import socket
import stat
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
FIXTURE = os.path.join(HERE, 'fixtures', 'user_pkg')
WS = os.environ.get('EXP2_WS') or os.path.expanduser('~/.cache/exp_assignment2_ws')
PLANNING_MD5 = 'c9821bcb163053e9fc3222c6782db3d8'     # exp_assignment2/PlanningAction

pytestmark = [pytest.mark.skipif(not os.path.exists(os.path.join(WS, 'devel', 'setup.bash')),
                                 reason='no catkin workspace at %s: bash tools/run setup' % WS),
              # one worker builds the session's overlays (pytest-xdist, tools/run test)
              pytest.mark.xdist_group('overlay')]


def original_env(package, *cmd, overlays, timeout=1200):
    """``bash tools/run original-env --package package cmd...`` -> CompletedProcess."""
    env = dict(os.environ, EXP2_OVERLAY_ROOT=str(overlays),
               ROS_HOME=str(overlays / 'ros_home'), PYTHONUNBUFFERED='1')
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    return subprocess.run(['bash', os.path.join(REPO, 'tools', 'run'), 'original-env',
                           '--package', str(package)] + list(cmd),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd='/',
                          universal_newlines=True, timeout=timeout)


def checksum(directory):
    """Every entry of ``directory`` (hidden ones and build outputs too): name, mode, content."""
    digest = hashlib.sha1()
    for root, dirs, files in os.walk(str(directory)):
        dirs.sort()
        for name in sorted(dirs + files):
            path = os.path.join(root, name)
            info = os.lstat(path)
            digest.update(('%s %o\n' % (os.path.relpath(path, str(directory)),
                                        info.st_mode)).encode())
            if stat.S_ISREG(info.st_mode):
                with open(path, 'rb') as f:
                    digest.update(f.read())
    return digest.hexdigest()


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


def failure_lines(proc):
    return [line for line in proc.stderr.splitlines() if 'failed' in line]


class Edited:
    """Replace text in a file of the package for the block, then restore it."""

    def __init__(self, path, old, new):
        self.path, self.old, self.new = str(path), old, new

    def __enter__(self):
        with open(self.path) as f:
            self.text = f.read()
        assert self.old in self.text
        with open(self.path, 'w') as f:
            f.write(self.text.replace(self.old, self.new))

    def __exit__(self, *exc):
        with open(self.path, 'w') as f:
            f.write(self.text)


@pytest.fixture(scope='module')
def built(tmp_path_factory):
    """The fixture package in a user's checkout (with a stray build/ and .git/), built."""
    root = tmp_path_factory.mktemp('overlay')
    package = root / 'exp_assignment2'
    shutil.copytree(FIXTURE, str(package))
    for junk in ('build/CMakeCache.txt', 'devel/setup.bash', '.git/HEAD'):
        os.makedirs(str((package / junk).parent), exist_ok=True)
        (package / junk).write_text('left by someone else\n')
    before = checksum(package)
    proc = original_env(package, 'true', overlays=root / 'overlays')
    assert proc.returncode == 0, proc.stderr
    assert 'building %s' % package in proc.stderr
    return package, root / 'overlays', before


def test_the_build_leaves_the_package_directory_unchanged(built):
    package, _overlays, before = built
    assert checksum(package) == before


def test_their_script_runs_with_their_own_types(built):
    package, overlays, _ = built
    proc = original_env(package, 'rosrun', 'exp_assignment2', 'report_types.py',
                        overlays=overlays)
    assert proc.returncode == 0, proc.stderr
    types = {line.split()[0]: line.split()[1:] for line in proc.stdout.splitlines()}
    assert set(types) == {'exp_assignment2/BallSighting', 'exp_assignment2/PlanningAction',
                          'exp_assignment2/PlanningGoal'}, proc.stdout
    assert types['exp_assignment2/PlanningAction'][0] == PLANNING_MD5
    for _md5, module_file in types.values():     # generated in the overlay's devel space
        assert module_file.startswith(str(overlays)), module_file
    assert 'is up to date' in proc.stderr


def test_names_resolve_to_their_package_and_ours_stays_reachable(built):
    package, overlays, _ = built
    script = '''
    rospack find exp_assignment2
    rospack find exp_assignment2_sim
    python3 -c "
import exp_assignment2.planning as p, exp_assignment2.minismach
from exp_assignment2.msg import BallSighting, Gesture, PlanningAction
import sys
print(p.__file__, sys.modules[Gesture.__module__].__file__, PlanningAction._md5sum)"
    roslaunch --args gazebo exp_assignment2_sim simulator.launch
    '''
    proc = original_env(package, 'bash', '-ec', script, overlays=overlays)
    assert proc.returncode == 0, proc.stderr
    theirs, ours, python, simulator = proc.stdout.split('\n')[:4]
    assert theirs.startswith(str(overlays))
    assert os.path.realpath(os.path.join(theirs, 'package.xml')) == str(package / 'package.xml')
    assert ours.startswith(str(overlays)) and ours.endswith('exp_assignment2_sim')
    planning, gesture, md5 = python.split()
    assert planning.endswith('src/exp_assignment2/planning.py')       # this repository's library
    assert not gesture.startswith(str(overlays)) and md5 == PLANNING_MD5
    assert os.path.realpath(simulator.split()[0]) == os.path.join(REPO, 'scripts', 'simulator.py')


def test_their_cpp_node_runs_from_their_launch_file(built):
    package, overlays, _ = built
    proc = original_env(package, 'roslaunch', '-p', str(free_port()), 'exp_assignment2',
                        'announce.launch', overlays=overlays, timeout=300)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr
    assert ('sighting_announcer: published a exp_assignment2/BallSighting (radius 42), '
            'action type exp_assignment2/PlanningAction') in proc.stdout


def test_an_unchanged_package_is_not_rebuilt_and_a_changed_one_is(built):
    package, overlays, _ = built
    log = next(overlays.glob('*/build.log'))
    built_at = log.stat().st_mtime
    proc = original_env(package, 'true', overlays=overlays)
    assert proc.returncode == 0 and 'is up to date' in proc.stderr and 'building' not in proc.stderr
    assert log.stat().st_mtime == built_at
    fields = 'from exp_assignment2.msg import BallSighting; print(BallSighting.__slots__)'
    with Edited(package / 'msg' / 'BallSighting.msg', 'float64 radius',
                'float64 radius\nfloat64 distance'):
        proc = original_env(package, 'python3', '-c', fields, overlays=overlays)
    assert proc.returncode == 0, proc.stderr
    assert 'building %s' % package in proc.stderr
    assert "'radius', 'distance'" in proc.stdout


def test_a_broken_message_gives_one_line_naming_it(built):
    package, overlays, _ = built
    with Edited(package / 'msg' / 'BallSighting.msg', 'float64 radius',
                'float64 radius\nfloot64 speed'):
        before = checksum(package)
        proc = original_env(package, 'true', overlays=overlays)
        assert checksum(package) == before
    assert proc.returncode != 0
    [line] = failure_lines(proc)
    assert '%s/msg/BallSighting.msg: ' % package in line and 'floot64' in line
    assert 'full log: %s' % overlays in line


def test_a_broken_cpp_node_gives_one_line_naming_file_and_line(built):
    package, overlays, _ = built
    with Edited(package / 'src' / 'sighting_announcer.cpp', 'sighting.cx = 400.0;',
                'sighting.cx = undeclared_centre;'):
        before = checksum(package)
        proc = original_env(package, 'true', overlays=overlays)
        assert checksum(package) == before
    assert proc.returncode != 0
    [line] = failure_lines(proc)
    assert '%s/src/sighting_announcer.cpp:17: ' % package in line
    assert 'undeclared_centre' in line and 'was not declared' in line


# built on its own, beside the module's package: another worker's group
@pytest.mark.xdist_group('overlay_renamed')
def test_a_package_named_otherwise_works_too(tmp_path):
    """my_dog: the template renamed, naming a catkin package Debian lacks."""
    package = tmp_path / 'my_dog'
    shutil.copytree(FIXTURE, str(package))
    for path in package.rglob('*'):
        if path.is_file():
            path.write_text(path.read_text().replace('exp_assignment2', 'my_dog'))
    cmake = package / 'CMakeLists.txt'
    cmake.write_text(cmake.read_text().replace('  actionlib\n)', '  actionlib\n  gazebo_ros_control\n)'))
    script = '''
    rosrun my_dog report_types.py
    python3 -c "import exp_assignment2.minismach; from exp_assignment2.msg import PlanningAction"
    roslaunch -p %d my_dog announce.launch
    ''' % free_port()
    proc = original_env(package, 'bash', '-ec', script, overlays=tmp_path / 'overlays')
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr
    assert 'stand-ins (Debian has none; found by CMake, provide nothing): gazebo_ros_control' \
        in proc.stderr
    assert 'my_dog/BallSighting' in proc.stdout and 'my_dog/PlanningAction %s' % PLANNING_MD5 \
        in proc.stdout
    assert 'sighting_announcer: published a my_dog/BallSighting' in proc.stdout

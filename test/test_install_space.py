"""The install space alone: ``catkin_make install`` of this package (and the
message stand-ins its nodes import, linked as tools/run links them: only
where the real one does not import) into a temporary prefix; then the
workspace's build and devel spaces are deleted and, with only that prefix
sourced in an emptied environment (no PYTHONPATH to src/, no ROS_PACKAGE_PATH
to the repository, a home of its own, so the grader's default workspace is
a new one), the dog world runs (``roslaunch exp_assignment2 sim_world.launch``:
/clock, /robot/odom, the camera and the dog's state), a rostest passes, and
the grader (``rosrun exp_assignment2 grade.py``) grades the ``works`` fixture
to ``passed``. No step's output may name the repository's folder.

The rostest's checker is test code, not installed: it is copied into a
package of its own (``exp2_install_check``), whose .test file includes the
installed launch file. One module-scoped build (about 25 s of CPU: four
packages, no tests, no C++), in an xdist group of its own.
"""
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.realpath(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import grading_fixtures  # noqa: E402

pytestmark = pytest.mark.xdist_group('install_space')
# the stand-ins this package's own nodes import (gazebo_msgs: the simulator's
# state interface; controller_manager_msgs, control_msgs: its controllers)
STAND_INS = ('gazebo_msgs', 'controller_manager_msgs', 'control_msgs')
ROSTEST = 'gazebo_state.test'       # the simulator's state interface, about 5 s
CHECK_PACKAGE = 'exp2_install_check'
CHECK_XML = '''<?xml version="1.0"?>
<package format="2"><name>%s</name><version>0.0.0</version>
  <description>test/nodes' checkers, for a rostest of the installed package</description>
  <maintainer email="exp_assignment2@example.com">exp_assignment2 developers</maintainer>
  <license>BSD</license></package>
''' % CHECK_PACKAGE
# /clock, the odometry, the dog's state and the camera, seen from a node of
# the install space's own Python: JSON of what came, after 3 simulated s
PROBE = r'''
import json, sys, time
import rospy
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import CompressedImage
from std_msgs.msg import String
seen = {}
def note(name, value):
    entry = seen.setdefault(name, {'count': 0, 'first': value})
    entry['count'] += 1
    entry['last'] = value
rospy.init_node('install_space_probe')
rospy.Subscriber('/clock', Clock, lambda m: note('clock', m.clock.to_sec()))
rospy.Subscriber('/robot/odom', Odometry, lambda m: note('odom', m.header.stamp.to_sec()))
rospy.Subscriber('/robot/state', String, lambda m: note('state', m.data))
rospy.Subscriber('/robot/camera1/image_raw/compressed', CompressedImage,
                 lambda m: note('camera', m.header.stamp.to_sec()))
deadline = time.monotonic() + float(sys.argv[1])
def done():
    return all(seen.get(k, {}).get('count', 0) >= 3 for k in ('clock', 'odom', 'camera')) \
        and 'state' in seen and seen['clock']['last'] - seen['clock']['first'] >= 3.0
while not done() and time.monotonic() < deadline:
    time.sleep(0.2)
print(json.dumps(seen))
'''


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def imports(module):
    return subprocess.run(['/usr/bin/python3', '-c', 'import ' + module],
                          env={'PATH': '/usr/bin:/bin'}, stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode == 0


def tail(text, lines=40):
    return '\n'.join(text.splitlines()[-lines:])


def log_tails(folder):
    """The end of each log in ``folder`` (the run's: build, roscore, commands)."""
    out = ''
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        with open(os.path.join(folder, name), errors='replace') as f:
            out += '\n%s:\n%s' % (name, tail(f.read(), 15))
    return out


def mentions_repo(folder):
    """Files under ``folder`` whose text names the repository's folder."""
    found = []
    for root, _dirs, files in os.walk(folder):
        for name in files:
            path = os.path.join(root, name)
            try:
                with open(path, errors='replace') as f:
                    if REPO + os.sep in f.read():
                        found.append(path)
            except OSError:
                pass
    return found


@pytest.fixture(scope='module')
def install(tmp_path_factory):
    """The install space, and how to run a command with only it sourced."""
    base = tmp_path_factory.mktemp('install_space')
    ws, prefix, home = base / 'ws', base / 'install', base / 'home'
    (ws / 'src').mkdir(parents=True)
    home.mkdir()
    os.symlink(REPO, str(ws / 'src' / 'exp_assignment2'))
    for name in STAND_INS:
        if not imports(name):
            os.symlink(os.path.join(REPO, 'tools', 'stand_ins', name), str(ws / 'src' / name))
    # an emptied environment: the build must not chain to tools/run's devel space
    bare = {'PATH': '/usr/bin:/bin:/usr/sbin:/sbin', 'HOME': str(home), 'LANG': 'C.UTF-8'}
    proc = subprocess.run(['catkin_make', '-C', str(ws), '-DPYTHON_EXECUTABLE=/usr/bin/python3',
                           '-DCATKIN_ENABLE_TESTING=OFF', '-DCMAKE_INSTALL_PREFIX=%s' % prefix,
                           'install'], env=bare, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=900)
    assert proc.returncode == 0, 'catkin_make install failed:\n' + tail(proc.stdout)
    for space in ('build', 'devel', 'src'):       # the install space alone from here on
        shutil.rmtree(str(ws / space))
    setup = str(prefix / 'setup.bash')

    def run(argv, log_dir, env=()):
        """``argv`` started with the install space sourced, its ROS logs in
        ``log_dir``, in a folder of the test's (not the repository)."""
        log_dir.mkdir(exist_ok=True)
        environ = dict(bare, ROS_HOME=str(log_dir), ROS_LOG_DIR=str(log_dir / 'log'),
                       PYTHONUNBUFFERED='1', **dict(env))
        return subprocess.Popen(['bash', '-c', 'source "$1" && shift && exec "$@"', 'bash',
                                 setup] + list(argv), env=environ, cwd=str(base),
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                universal_newlines=True, start_new_session=True)
    return {'base': base, 'prefix': str(prefix), 'run': run}


def finish(proc, timeout):
    """(exit status, output) of ``proc``; its process group ended if it overstays."""
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        return None, out
    return proc.returncode, out


def test_the_environment_holds_the_install_space_only(install):
    log = install['base'] / 'env'
    status, out = finish(install['run'](['env'], log), 60)
    assert status == 0, out
    env = dict(line.split('=', 1) for line in out.splitlines() if '=' in line)
    leaks = {k: v for k, v in env.items() if REPO in v}
    assert not leaks, 'the sourced install space names the repository: %s' % leaks
    assert install['prefix'] in env.get('PYTHONPATH', ''), env.get('PYTHONPATH')
    assert env.get('ROS_PACKAGE_PATH', '').startswith(install['prefix']), env


def test_the_dog_world_runs(install):
    log, port = install['base'] / 'dog_world', free_port()
    master = {'ROS_MASTER_URI': 'http://localhost:%d' % port}
    launch = install['run'](['roslaunch', '-p', str(port), 'exp_assignment2',
                             'sim_world.launch'], log, env=master)
    try:
        status, out = finish(install['run'](['/usr/bin/python3', '-c', PROBE, '120'], log,
                                            env=master), 180)
    finally:
        os.killpg(launch.pid, signal.SIGINT)      # as Ctrl-C
        launched = finish(launch, 60)[1]
    assert status == 0, 'the probe failed:\n%s\nroslaunch:\n%s' % (tail(out), tail(launched))
    seen = json.loads(out.strip().splitlines()[-1])
    said = '\nroslaunch said:\n' + tail(launched)
    for key, what in (('clock', '/clock'), ('odom', '/robot/odom'),
                      ('camera', 'the camera (/robot/camera1/image_raw/compressed)')):
        entry = seen.get(key) or {}
        assert entry.get('count', 0) >= 3 and entry['last'] > entry['first'], (
            '%s did not advance in 120 s: %s%s' % (what, entry, said))
    assert seen['clock']['last'] - seen['clock']['first'] >= 3.0, seen['clock']
    assert 'state' in seen, 'the dog\'s state machine published no /robot/state' + said
    assert not mentions_repo(str(log)), mentions_repo(str(log))


def test_a_rostest_passes(install):
    """``gazebo_state.test`` against the installed simulator, launch files and
    message stand-ins, its checker from a package of its own."""
    log = install['base'] / 'rostest'
    check = install['base'] / 'check' / CHECK_PACKAGE
    shutil.copytree(os.path.join(HERE, 'nodes'), str(check / 'nodes'))
    (check / 'package.xml').write_text(CHECK_XML)
    with open(os.path.join(HERE, ROSTEST)) as f:
        text = f.read()
    checkers = os.listdir(os.path.join(HERE, 'nodes'))
    text = re.sub(r'pkg="exp_assignment2"(\s+type="([^"]+)")',
                  lambda m: ('pkg="%s"' % CHECK_PACKAGE if m.group(2) in checkers
                             else 'pkg="exp_assignment2"') + m.group(1), text)
    assert 'pkg="%s"' % CHECK_PACKAGE in text
    (check / ROSTEST).write_text(text)
    status, out = finish(install['run'](
        ['bash', '-c', 'ROS_PACKAGE_PATH=$ROS_PACKAGE_PATH:%s exec rostest --text %s %s'
         % (check.parent, CHECK_PACKAGE, ROSTEST)], log), 300)
    assert status == 0 and 'RESULT: SUCCESS' in out, (
        'rostest %s from the install space failed (exit %s):\n%s' % (ROSTEST, status,
                                                                    tail(out, 60)))
    assert not mentions_repo(str(log)), mentions_repo(str(log))


def test_the_grader_grades_the_works_fixture(install):
    """The grader's sandbox, the original-code environment and the launch
    surface, all found in the install space: ``works`` is ``passed``."""
    log = install['base'] / 'grade'
    folder = grading_fixtures.make_folder(str(install['base'] / 'class'), ['works'])
    out_dir = str(install['base'] / 'report')
    status, out = finish(install['run'](['rosrun', 'exp_assignment2', 'grade.py', folder,
                                         '--out', out_dir, '--duration', '20',
                                         '--real-time-factor', '2'], log), 600)
    report_file = os.path.join(out_dir, 'report.json')
    assert os.path.exists(report_file), 'grade.py exited %s with no report:\n%s' % (
        status, tail(out))
    with open(report_file) as f:
        works = {s['name']: s for s in json.load(f)['submissions']}['works']
    assert works['verdict'] == 'passed', 'works is %s: %s\ngrade.py said:\n%s%s' % (
        works['verdict'], works.get('reason'), tail(out, 15),
        log_tails(os.path.join(out_dir, 'runs', 'works', 'work', 'logs')))
    assert status == 0, out
    assert not mentions_repo(os.path.join(out_dir, 'runs')), mentions_repo(
        os.path.join(out_dir, 'runs'))

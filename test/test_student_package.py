"""A student's whole package, run the way its user runs it:

    bash tools/run original-env --package test/fixtures/student_pkg \\
        roslaunch exp_assignment2 gazebo_world.launch

(on a port of its own), then test/student_package.test's checker with
``rostest --reuse-master`` against that system, from this workspace. The
launch output must be clean: no ERROR line, no traceback. Then it is stopped
as a user stops it (SIGINT), and must end within roslaunch's own time.
"""
import os
import signal
import socket
import subprocess
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
FIXTURE = os.path.join(HERE, 'fixtures', 'student_pkg')
UP = 900.0      # wall s for the overlay to build (C++ included) and the master to come up


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


def master_up(env):
    return subprocess.run(['rosparam', 'get', '/run_id'], env=env, stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode == 0


def tail(path, lines=80):
    with open(path, errors='replace') as f:
        return ''.join(f.readlines()[-lines:])


def test_a_students_package_runs_as_its_user_runs_it(tmp_path):
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI='http://localhost:%d' % port,
               ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / 'log'), PYTHONUNBUFFERED='1')
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    env.pop('DISPLAY', None)            # gui:=true's default: gzclient says it has no display
    log = tmp_path / 'roslaunch.out'
    with open(str(log), 'w') as out:
        launch = subprocess.Popen(
            ['bash', os.path.join(REPO, 'tools', 'run'), 'original-env', '--package', FIXTURE,
             'roslaunch', '-p', str(port), 'exp_assignment2', 'gazebo_world.launch'],
            env=env, stdout=out, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.monotonic() + UP
        while not master_up(env):       # nothing to wait on but the master's answer
            assert launch.poll() is None, 'the launch ended:\n' + tail(str(log))
            assert time.monotonic() < deadline, 'no master after %.0f s:\n%s' % (UP, tail(
                str(log)))
            time.sleep(1.0)
        check = subprocess.run(['rostest', '--reuse-master', '--text', 'exp_assignment2',
                                'student_package.test'], env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, universal_newlines=True, timeout=600)
    finally:
        if launch.poll() is None:
            os.killpg(launch.pid, signal.SIGINT)
        try:
            launch.wait(timeout=60)
        except subprocess.TimeoutExpired:
            os.killpg(launch.pid, signal.SIGKILL)
            launch.wait()
            pytest.fail('the launch did not stop within 60 s of SIGINT:\n' + tail(str(log)))
    report = '\n'.join(check.stdout.splitlines()[-60:])
    assert check.returncode == 0 and 'RESULT: SUCCESS' in check.stdout, report
    with open(str(log), errors='replace') as f:
        text = f.read()
    bad = [l for l in text.splitlines() if '[ERROR]' in l or 'Traceback' in l]
    assert not bad, 'the launch output is not clean:\n' + '\n'.join(bad[:20])

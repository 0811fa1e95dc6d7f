"""Bad launch arguments stop the launch within seconds, with one line naming
the argument, its value and what is accepted, and ``tools/run main`` (which
runs tools/roslaunch_required.py) exits non-zero, although roslaunch itself
exits 0 when a required node dies. Needs the built workspace (tools/run test)."""
import os
import shutil
import socket
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
LAUNCHER = os.path.join(os.path.dirname(HERE), 'tools', 'roslaunch_required.py')

CASES = [
    ('camera_width:=1', '~camera_width = 1 is refused; accepted: a whole number of pixels in'),
    ('camera_width:=100000', '~camera_width = 100000 is refused; accepted: a whole number of '
                             'pixels in'),
    ('camera_width:=nan', '~camera_width = nan is refused; accepted: a whole number of pixels'),
    ('seed:=abc', 'seed:=abc is refused; accepted: a whole number'),
    ('robot_model:=bogus', 'robot_model:=bogus is refused; accepted: rep103 (+angular.z turns '
                           'left) or original'),
]


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


def workspace_ready():
    if shutil.which('rospack') is None:
        return False
    found = subprocess.run(['rospack', 'find', 'exp_assignment2'], stdout=subprocess.PIPE,
                           stderr=subprocess.DEVNULL, universal_newlines=True)
    return found.returncode == 0


@pytest.mark.skipif(not workspace_ready(), reason='no catkin workspace (tools/run test)')
@pytest.mark.parametrize('arg,line', CASES, ids=[c[0] for c in CASES])
def test_a_bad_argument_stops_the_launch_with_one_line(arg, line, tmp_path):
    env = dict(os.environ, ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / 'log'),
               PYTHONUNBUFFERED='1')
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    start = time.monotonic()
    proc = subprocess.run([sys.executable, LAUNCHER, '-p', str(free_port()), 'exp_assignment2',
                           'sim_world.launch', arg], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, env=env, timeout=120,
                          universal_newlines=True)
    took = time.monotonic() - start
    naming = [l for l in proc.stdout.splitlines() if line in l]
    assert proc.returncode != 0, proc.stdout[-3000:]
    # a few seconds on an idle machine (8 s measured); a loaded one needs margin
    assert took < 60.0, 'the launch took %.0f s to stop' % took
    assert len(naming) == 1, proc.stdout[-3000:]
    assert 'Traceback' not in proc.stdout

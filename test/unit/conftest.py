"""A ROS master of a test's own, for the few unit tests that need one."""
import socket
import subprocess
import time

import pytest

from original_env_helpers import base_env


@pytest.fixture
def ros_master(tmp_path):
    """The environment of a rosmaster on a free port, started for the test."""
    with socket.socket() as s:
        s.bind(('localhost', 0))
        port = s.getsockname()[1]
    env = dict(base_env(), ROS_MASTER_URI='http://localhost:%d' % port, ROS_HOME=str(tmp_path))
    proc = subprocess.Popen(['rosmaster', '--core', '-p', str(port)], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 30
    while subprocess.run(['rosparam', 'list'], env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL).returncode != 0:
        assert time.monotonic() < deadline, 'no ROS master after 30 s'
        time.sleep(0.2)
    yield env
    proc.terminate()
    proc.wait(10)

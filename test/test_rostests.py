"""Runs every rostest launch file in test/ (each starts its own master).

They run one after another: two rostests on one port would collide. A failing
rostest shows the tail of its output here.
"""
import glob
import os
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS = sorted(glob.glob(os.path.join(HERE, '*.test')))


@pytest.mark.parametrize('launch', TESTS, ids=[os.path.basename(t) for t in TESTS])
def test_rostest(launch, tmp_path):
    env = dict(os.environ, ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / 'log'),
               PYTHONUNBUFFERED='1')
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    proc = subprocess.run(['rostest', '--text', 'exp_assignment2', os.path.basename(launch)],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                          timeout=600, universal_newlines=True)
    tail = '\n'.join(proc.stdout.splitlines()[-60:])
    assert proc.returncode == 0, 'rostest %s failed:\n%s' % (os.path.basename(launch), tail)
    assert 'SUMMARY' in proc.stdout and 'RESULT: SUCCESS' in proc.stdout, tail

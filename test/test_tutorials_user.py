"""A student's package built on the actionlib tutorial's types, which every ROS
Noetic desktop-full had and Debian has not (test/fixtures/tutorials_user: its
package.xml and CMakeLists name actionlib_tutorials, its own message is made
of FibonacciGoal and FibonacciResult, a Python node imports
actionlib_tutorials.msg and a C++ program includes its headers), built and run
through ``bash tools/run original-env --package DIR`` as a student would: the
stand-in (tools/stand_ins/actionlib_tutorials) is what CMake, rospack, Python
and the compiler find, with Noetic's md5sums. Needs the built workspace; about
a minute on two cores."""
import os
import shutil

import pytest

from test_overlay import WS, original_env

HERE = os.path.dirname(os.path.abspath(__file__))
GOAL_MD5 = '6889063349a00b249bd1661df429d822'   # actionlib_tutorials/FibonacciGoal, Noetic

pytestmark = [pytest.mark.skipif(not os.path.exists(os.path.join(WS, 'devel', 'setup.bash')),
                                 reason='no catkin workspace at %s: bash tools/run setup' % WS),
              pytest.mark.xdist_group('overlay')]


def test_a_package_naming_actionlib_tutorials_builds_and_runs(tmp_path, ros_master,
                                                                monkeypatch):
    package = tmp_path / 'tutorials_user'
    shutil.copytree(os.path.join(HERE, 'fixtures', 'tutorials_user'), str(package))
    # the node's master: the test's own (original_env passes os.environ on)
    monkeypatch.setenv('ROS_MASTER_URI', ros_master['ROS_MASTER_URI'])
    proc = original_env(package, 'bash', '-ec',
                        'rospack find actionlib_tutorials;'
                        ' timeout 120 rosrun tutorials_user fibonacci_pair.py;'
                        ' rosrun tutorials_user fibonacci_md5',
                        overlays=tmp_path / 'overlays')
    assert proc.returncode == 0, proc.stderr[-3000:]
    found, python, cpp = proc.stdout.splitlines()[-3:]
    stand_in = os.path.join('tools', 'stand_ins', 'actionlib_tutorials')
    assert os.path.realpath(found).endswith(stand_in), found
    kind, md5, record_md5, sequence = python.split(' ', 3)
    assert (kind, md5) == ('actionlib_tutorials/FibonacciGoal', GOAL_MD5)
    assert sequence == '0 1 1 2 3 5 8 13'       # the server's answer, through actionlib
    # C++ sees the same types: the stand-in's generated headers
    assert cpp.split() == [kind, md5, record_md5]
    # CMake found the stand-in itself, not the overlay's empty config for a missing package
    assert not [line for line in proc.stderr.splitlines()
                if 'stand-ins (Debian has none' in line and 'actionlib_tutorials' in line]

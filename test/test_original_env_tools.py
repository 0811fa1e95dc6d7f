"""What a student's launch file or terminal runs by name in the original
environment (tools/original_env/shell.sh) is there, as in Noetic: ``xacro``
on PATH is ROS's xacro (``load_yaml`` works under Debian's PyYAML 6, which
PyPI's script fails), and tf's and tf2_ros's tools (``tf_echo``,
``view_frames``, ``static_transform_publisher``) are found by rosrun.

Needs the built catkin workspace (``bash tools/run setup``); skipped without."""
import os
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SHELL = os.path.join(os.path.dirname(HERE), 'tools', 'original_env', 'shell.sh')
WS = os.environ.get('EXP2_WS') or os.path.expanduser('~/.cache/exp_assignment2_ws')

pytestmark = pytest.mark.skipif(not os.path.exists(os.path.join(WS, 'devel', 'setup.bash')),
                                reason='no catkin workspace at %s: bash tools/run setup' % WS)

SCRIPT = '''
command -v xacro
xacro robot.xacro
for tool in "tf tf_echo" "tf view_frames" "tf static_transform_publisher" \
            "tf2_ros static_transform_publisher"; do
    rosrun --prefix "echo found" $tool
done
'''


def test_xacro_on_path_and_the_tf_tools_are_ross(tmp_path):
    (tmp_path / 'dims.yaml').write_text('chassis: {mass: 5.0}\n')
    (tmp_path / 'robot.xacro').write_text(
        '<robot name="dog" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:property name="dims" value="${load_yaml(\'dims.yaml\')}"/>'
        '<link name="chassis"><inertial><mass value="${dims.chassis.mass}"/></inertial>'
        '</link></robot>')
    env = dict(os.environ, ROS_HOME=str(tmp_path / 'ros_home'))
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    proc = subprocess.run(['bash', SHELL, 'bash', '-ec', SCRIPT], cwd=str(tmp_path), env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[0] == os.path.join(WS, 'original_env_bin', 'xacro'), lines[0]
    assert '<mass value="5.0"/>' in proc.stdout
    found = [line.split()[1] for line in lines if line.startswith('found ')]
    assert found == ['/usr/lib/tf/tf_echo', '/usr/lib/tf/view_frames',
                     '/usr/lib/tf/static_transform_publisher',
                     '/usr/lib/tf2_ros/static_transform_publisher'], proc.stdout + proc.stderr


DESKTOP_FULL_NODES = ['joint_state_publisher joint_state_publisher',
                      'joint_state_publisher_gui joint_state_publisher_gui',
                      'image_view image_view', 'dynamic_reconfigure dynparam']


def test_desktop_full_nodes_a_launch_file_names_are_found_by_rosrun(tmp_path):
    """Nodes every desktop-full had, which launch files of URDF models and
    cameras start (Debian's, installed by the shell: docs/original_env_supplies.md)."""
    env = dict(os.environ, ROS_HOME=str(tmp_path / 'ros_home'))
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    script = ''.join('rosrun --prefix "echo found" %s\n' % node for node in DESKTOP_FULL_NODES)
    proc = subprocess.run(['bash', SHELL, 'bash', '-ec', script], cwd=str(tmp_path), env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    found = [line.split()[1] for line in proc.stdout.splitlines() if line.startswith('found ')]
    assert [os.path.basename(path) for path in found] == \
        [node.split()[1] for node in DESKTOP_FULL_NODES], proc.stdout + proc.stderr

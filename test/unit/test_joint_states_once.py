"""A joint comes once per stamp on ``/robot/joint_states`` when the robot's
diff drive publishes its wheels too (``publishWheelJointState``, as many
students' robots say) beside gazebo_ros_control's joint_state_controller:
twice, robot_state_publisher printed ``TF_REPEATED_DATA`` warnings for the
wheels. The simulator node runs on a ROS master of the test's own."""
import os
import subprocess
import sys

import pytest
import yaml

from original_env_helpers import PYTHON

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
URDF = os.path.join(REPO, 'urdf')

LISTEN = r'''
import collections, time
import rospy
from sensor_msgs.msg import JointState
rospy.init_node('listener', disable_signals=True)
seen = collections.Counter()
def on_states(msg):
    for name in msg.name:
        seen[(msg.header.stamp.to_nsec(), name)] += 1
rospy.Subscriber('/robot/joint_states', JointState, on_states, queue_size=100)
deadline = time.monotonic() + 60
while len(seen) < 200 and time.monotonic() < deadline:
    time.sleep(0.1)
print('JOINTS', ' '.join(sorted({name for _, name in seen})))
print('TWICE', sum(1 for n in seen.values() if n > 1))
'''


def test_a_wheel_published_by_the_diff_drive_is_left_out_of_the_controllers(ros_master,
                                                                           tmp_path):
    with open(os.path.join(URDF, 'robot.urdf')) as f:
        robot = f.read()
    anchor = '<plugin name="differential_drive_controller"'
    assert anchor in robot
    start = robot.index('>', robot.index(anchor)) + 1
    robot = robot[:start] + '<publishWheelJointState>true</publishWheelJointState>' + \
        robot[start:]
    (tmp_path / 'robot.urdf').write_text(robot)
    world = {'models': [{'name': 'arena', 'urdf': os.path.join(URDF, 'arena.urdf')},
                        {'name': 'robot', 'urdf': str(tmp_path / 'robot.urdf'),
                         'namespace': 'robot', 'pose': [0.0, 0.0, 0.1, 0.0]}],
             'real_time_factor': 0}
    (tmp_path / 'world.yaml').write_text(yaml.safe_dump(world))
    env = ros_master
    for cmd in (['rosparam', 'set', '/use_sim_time', 'true'],
                ['rosparam', 'load', str(tmp_path / 'world.yaml'), '/gazebo'],
                ['rosparam', 'load', os.path.join(REPO, 'config', 'robot_controllers.yaml'),
                 '/robot']):
        subprocess.run(cmd, env=env, check=True, timeout=30)
    simulator = subprocess.Popen(
        [PYTHON, os.path.join(REPO, 'scripts', 'simulator.py'), '__name:=gazebo',
         '_urdf_dir:=' + URDF], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        universal_newlines=True)
    try:
        proc = subprocess.run([PYTHON, '-c', LISTEN], env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, universal_newlines=True, timeout=90)
    finally:
        simulator.terminate()
        out, _ = simulator.communicate(timeout=30)
    assert proc.returncode == 0, proc.stderr
    lines = dict(line.split(' ', 1) for line in proc.stdout.splitlines()
                 if line.startswith(('JOINTS', 'TWICE')))
    assert lines.get('JOINTS', '').split() == ['head_joint', 'joint_left_wheel',
                                               'joint_right_wheel'], proc.stdout + out
    assert lines['TWICE'] == '0', proc.stdout + out[-3000:]


if __name__ == '__main__':
    sys.exit(pytest.main([__file__]))

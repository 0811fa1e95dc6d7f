"""gazebo_ros_control's topics as a student's robot and YAML use them (the
simulator node on a ROS master of the test's own):

* a joint comes once per stamp on ``/robot/joint_states`` when the robot's
  diff drive publishes its wheels too (``publishWheelJointState``) beside the
  joint_state_controller: twice, robot_state_publisher printed
  ``TF_REPEATED_DATA`` warnings for the wheels;
* an ``effort_controllers/JointPositionController`` publishes
  ``<name>/state`` (control_msgs/JointControllerState) as ros_controllers'
  does: set point, position, error and the YAML's PID gains."""
import os
import subprocess
import sys

import pytest
import yaml

from original_env_helpers import PYTHON

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
URDF = os.path.join(REPO, 'urdf')

CONTROLLERS = {'joint_state_controller': {'type': 'joint_state_controller/JointStateController',
                                          'publish_rate': 50},
               'head_controller': {'type': 'effort_controllers/JointPositionController',
                                   'joint': 'head_joint',
                                   'pid': {'p': 10.0, 'i': 0.1, 'd': 1.0, 'i_clamp': 2.0}}}

LISTEN = r'''
import collections, time
import rospy
from control_msgs.msg import JointControllerState
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64
rospy.init_node('listener', disable_signals=True)
seen, states = collections.Counter(), []
def on_joints(msg):
    for name in msg.name:
        seen[(msg.header.stamp.to_nsec(), name)] += 1
rospy.Subscriber('/robot/joint_states', JointState, on_joints, queue_size=100)
rospy.Subscriber('/robot/head_controller/state', JointControllerState, states.append,
                 queue_size=100)
command = rospy.Publisher('/robot/head_controller/command', Float64, queue_size=1, latch=True)
command.publish(Float64(0.5))
deadline = time.monotonic() + 60
while time.monotonic() < deadline and (len(seen) < 200 or not states or
                                       abs(states[-1].process_value - 0.5) > 0.01):
    time.sleep(0.1)
print('JOINTS', ' '.join(sorted({name for _, name in seen})))
print('TWICE', sum(1 for n in seen.values() if n > 1))
last = states[-1]
print('STATE %.2f %.2f %.2f %g %g %g %g' % (last.set_point, last.process_value, last.error,
                                           last.p, last.i, last.d, last.i_clamp))
stamps = [m.header.stamp.to_sec() for m in states]
print('STEP %.3f' % min(b - a for a, b in zip(stamps, stamps[1:]) if b > a))
'''


def test_joints_once_and_an_effort_controllers_state(ros_master, tmp_path):
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
    (tmp_path / 'controllers.yaml').write_text(yaml.safe_dump(CONTROLLERS))
    env = ros_master
    for cmd in (['rosparam', 'set', '/use_sim_time', 'true'],
                ['rosparam', 'load', str(tmp_path / 'world.yaml'), '/gazebo'],
                ['rosparam', 'load', str(tmp_path / 'controllers.yaml'), '/robot']):
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
                 if line.startswith(('JOINTS', 'TWICE', 'STATE', 'STEP')))
    assert lines.get('JOINTS', '').split() == ['head_joint', 'joint_left_wheel',
                                               'joint_right_wheel'], proc.stdout + out
    assert lines['TWICE'] == '0', proc.stdout + out[-3000:]
    set_point, position, error, *gains = lines['STATE'].split()
    assert (set_point, position, gains) == ('0.50', '0.50', ['10', '0.1', '1', '2']), lines
    assert abs(float(error)) <= 0.01
    # every update (time_step 0.01; a loaded machine may drop a message on its way)
    assert lines['STEP'] == '0.010', lines


if __name__ == '__main__':
    sys.exit(pytest.main([__file__]))

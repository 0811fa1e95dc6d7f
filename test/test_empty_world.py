"""gazebo_ros' empty_world.launch included as students include it, run in
``tools/run original-env`` on a port of its own: the simulator takes the
parameters the launch file sets under /gazebo (``enable_ros_network`` always,
``pub_clock_frequency`` with ``use_clock_frequency:=true``) and does what
gazebo_ros does with them.
"""
import os
import signal
import socket
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
UP = 300.0       # wall s for original-env's set-up and the simulator to start

# The steps between six /clock stamps (ns), then the /gazebo/ services and topics.
PROBE = r'''
import threading
import rospy, rosservice
from rosgraph_msgs.msg import Clock
rospy.init_node('probe', anonymous=True, disable_signals=True)
stamps, six = [], threading.Event()
def on_clock(msg):
    stamps.append(msg.clock.to_nsec())
    if len(stamps) == 7:
        six.set()
sub = rospy.Subscriber('/clock', Clock, on_clock)
assert six.wait(120), 'no /clock'
sub.unregister()
print('steps:', *(b - a for a, b in zip(stamps[1:], stamps[2:])))
print('names:', *(s for s in rosservice.get_service_list() if s.startswith('/gazebo/')))
print('names:', *(t for t, _ in rospy.get_published_topics() if t.startswith('/gazebo/')))
'''


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


def run_empty_world(tmp_path, *args):
    """(launch output, /clock steps in ns, /gazebo/ services and topics) of
    empty_world.launch with ``args``."""
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI='http://localhost:%d' % port,
               ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / 'log'), PYTHONUNBUFFERED='1')
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    log = tmp_path / 'roslaunch.out'
    with open(str(log), 'w') as out:
        launch = subprocess.Popen(
            ['bash', os.path.join(REPO, 'tools', 'run'), 'original-env', 'roslaunch', '-p',
             str(port), 'gazebo_ros', 'empty_world.launch', 'gui:=false'] + list(args),
            env=env, stdout=out, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        probe = subprocess.run(['/usr/bin/python3', '-c', PROBE], env=env, timeout=UP,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               universal_newlines=True)
    finally:
        os.killpg(launch.pid, signal.SIGINT)
        try:
            launch.wait(timeout=60)
        except subprocess.TimeoutExpired:
            os.killpg(launch.pid, signal.SIGKILL)
            launch.wait()
    with open(str(log), errors='replace') as f:
        output = f.read()
    assert probe.returncode == 0, probe.stdout[-2000:] + '\n' + output[-3000:]
    said = [line.split() for line in probe.stdout.splitlines()]
    return (output, [int(n) for words in said if words[:1] == ['steps:'] for n in words[1:]],
            [n for words in said if words[:1] == ['names:'] for n in words[1:]])


def steps_of(steps, period):
    """/clock came every ``period`` ns: the simulator leaves out a tick only
    when two fall within a wall millisecond (catching up after a stall)."""
    return min(steps) == period and all(s % period == 0 for s in steps)


def clean(output):
    return [l for l in output.splitlines()
            if '[ERROR]' in l or '[FATAL]' in l or 'Traceback' in l or 'has died' in l]


@pytest.mark.xdist_group('empty_world')
def test_included_as_is_it_publishes_every_step_and_offers_gazebos_services(tmp_path):
    output, steps, services = run_empty_world(tmp_path)
    assert clean(output) == [], output[-3000:]
    assert steps_of(steps, 10000000), steps      # every 0.01 s step
    assert {'/gazebo/spawn_urdf_model', '/gazebo/get_model_state',
            '/gazebo/model_states'} <= set(services)


@pytest.mark.xdist_group('empty_world')
def test_its_clock_frequency_and_network_switch_are_honoured(tmp_path):
    output, steps, services = run_empty_world(tmp_path, 'use_clock_frequency:=true',
                                              'pub_clock_frequency:=20',
                                              'enable_ros_network:=false')
    assert clean(output) == [], output[-3000:]
    assert steps_of(steps, 50000000), steps      # 20 Hz of simulated time
    assert [s for s in services if not s.endswith(('/get_loggers', '/set_logger_level'))] == []
    assert 'enable_ros_network is false: no /gazebo services or topics, only /clock' in output

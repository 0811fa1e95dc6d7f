"""The simulator node playing a ball script, started twice with the same
seed: once by its launch argument (``ball_script:=``) with nobody touching
the ball, once by ``EXP2_BALL_SCRIPT`` with a student's node pushing it
(cmd_vel, set_model_state, set_link_state, all answered with success). The
ground truth a grader reads has the same ball at the same simulated times;
what the node publishes (get_model_state, the ball's odometry,
/gazebo/model_states) is where the script has it. Needs the built workspace
(tools/run test)."""
import json
import os
import socket
import subprocess
import tempfile
import threading

import pytest

from exp_assignment2.sim import ball_script
from test_launch_args import free_port, workspace_ready

pytestmark = pytest.mark.skipif(not workspace_ready(), reason='no catkin workspace')
SETTING = '{"seed": 3, "duration": 40}'       # 40 s: hidden 4-6 s first, then shown
UNTIL = 20.0                                  # s of simulated time each run lasts

WORLD = '''bounds: [-8.8, 8.8, -8.8, 8.8]
models:
  - {name: arena, urdf: arena.urdf}
  - {name: human, urdf: human.urdf, pose: [-7.0, 7.0, 0.0, -0.785]}
  - {name: kennel, urdf: kennel.urdf, pose: [7.0, 7.0, 0.0, 0.0]}
  - {name: ball, description: /ball_description, pose: [-7.0, 6.0, 0.5, 0.0], namespace: ball}
'''
LAUNCH = '''<launch>
  <arg name="ball_script" default=""/>
  <param name="ball_description" textfile="$(find exp_assignment2)/urdf/ball.urdf"/>
  <include file="$(find exp_assignment2)/launch/include/simulator_node.launch">
    <arg name="world" value="%s"/>
    <arg name="real_time_factor" value="0"/>
    <arg name="ball_script" value="$(arg ball_script)"/>
  </include>
</launch>
'''

# What the node says of the ball until UNTIL: get_model_state and odometry
# (stamped), model_states (with the last /clock); ``push``: a student's node too.
PROBE = r'''
import json, random, sys, threading
import rospy
from gazebo_msgs.msg import LinkState, ModelState, ModelStates
from gazebo_msgs.srv import GetModelState, SetLinkState, SetModelState
from geometry_msgs.msg import Pose, Point, Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
push, until = sys.argv[1] == 'push', float(sys.argv[2])
rospy.init_node('probe', disable_signals=True)
out = {'get': [], 'odom': [], 'states': [], 'answers': []}
clock = [0.0]
done = threading.Event()
def on_clock(msg):
    clock[0] = msg.clock.to_sec()
    if clock[0] >= until:
        done.set()
def on_states(msg):
    if 'ball' in msg.name:
        p = msg.pose[msg.name.index('ball')].position
        out['states'].append([clock[0], p.x, p.y, p.z])
def on_odom(msg):
    p = msg.pose.pose.position
    out['odom'].append([msg.header.stamp.to_sec(), p.x, p.y, p.z])
rospy.Subscriber('/clock', Clock, on_clock)
rospy.Subscriber('/gazebo/model_states', ModelStates, on_states)
rospy.Subscriber('/ball/odom', Odometry, on_odom)
rospy.wait_for_service('/gazebo/get_model_state', 60)
get = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
set_model = rospy.ServiceProxy('/gazebo/set_model_state', SetModelState)
set_link = rospy.ServiceProxy('/gazebo/set_link_state', SetLinkState)
cmd = rospy.Publisher('/ball/cmd_vel', Twist, queue_size=10)
rng = random.Random(5)
while not done.wait(0.05):
    got = get('ball', 'world')
    p = got.pose.position
    out['get'].append([got.header.stamp.to_sec(), p.x, p.y, p.z])
    if push:
        twist = Twist()
        twist.linear.x, twist.linear.y = rng.uniform(-2, 2), rng.uniform(-2, 2)
        cmd.publish(twist)
        there = Pose(position=Point(rng.uniform(-5, 5), rng.uniform(-5, 5), 0.5))
        if rng.random() < 0.3:
            out['answers'].append(set_model(ModelState('ball', there, Twist(), 'world')).success)
        if rng.random() < 0.1:
            out['answers'].append(set_link(LinkState('ball::ball_link', there, Twist(),
                                                     'world')).success)
print('PROBE ' + json.dumps(out))
'''


class Truth(object):
    """A grader's socket: the records the simulator sends."""

    def __init__(self, path):
        self.server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self.server.bind(path)
        self.server.listen(1)
        self.records = []
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self):
        conn, _ = self.server.accept()
        with conn, conn.makefile('r') as lines:
            for line in lines:
                self.records.append(json.loads(line))

    def close(self):
        self.server.close()
        self.thread.join(10)


def run(tmp_path, name, push, launch_args=(), env_script=None):
    """(ground truth records, what the probe saw, roslaunch's output) of one run."""
    folder = tmp_path / name
    folder.mkdir()
    (folder / 'world.yaml').write_text(WORLD)
    (folder / 'ball.launch').write_text(LAUNCH % (folder / 'world.yaml'))
    sock = os.path.join(tempfile.mkdtemp(prefix='exp2-ball-'), 'truth.sock')
    truth = Truth(sock)
    port = free_port()
    env = dict(os.environ, ROS_HOME=str(folder), ROS_LOG_DIR=str(folder / 'log'),
               ROS_MASTER_URI='http://localhost:%d' % port, PYTHONUNBUFFERED='1',
               EXP2_GRADER_SOCKET=sock)
    env.pop('EXP2_BALL_SCRIPT', None)
    if env_script is not None:
        env['EXP2_BALL_SCRIPT'] = env_script
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    launch = subprocess.Popen(['roslaunch', '-p', str(port), str(folder / 'ball.launch')]
                              + list(launch_args), stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, env=env, universal_newlines=True)
    try:
        probe = subprocess.run(['/usr/bin/python3', '-c', PROBE, 'push' if push else 'watch',
                                str(UNTIL)], env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, universal_newlines=True, timeout=300)
    finally:
        launch.terminate()
        output = launch.communicate(timeout=60)[0]
        truth.close()
    said = [l for l in probe.stdout.splitlines() if l.startswith('PROBE ')]
    assert probe.returncode == 0 and said, probe.stdout[-3000:] + output[-3000:]
    return truth.records, json.loads(said[0][len('PROBE '):]), output


def on_script(script, start, samples, before=0.0, after=0.0):
    """Samples (t, x, y, z) not where the script has the ball at t (or from
    ``before`` s before it to ``after`` s after it, every step's place tried)."""
    wrong = []
    for t, x, y, z in samples:
        tries = [t + k * 0.01 for k in range(-int(round(before / 0.01)),
                                             int(round(after / 0.01)) + 1)]
        if not any(max(abs(a - b) for a, b in zip(
                ball_script.play(script, when - start)[:3], (x, y, z))) < 1e-3
                for when in tries):
            wrong.append((t, x, y, z))
    return wrong


def test_two_runs_of_a_seed_have_the_same_ball_whatever_the_students_node_does(tmp_path):
    calm, watched, said = run(tmp_path, 'calm', False,
                              launch_args=['ball_script:=' + SETTING])
    pushed, pushing, _ = run(tmp_path, 'pushed', True, env_script=SETTING)
    assert "the ball follows the course's script (seed 3, 40 s)" in said, said[-3000:]
    tracks = []
    for records in (calm, pushed):
        hello = records[0]
        assert hello['kind'] == 'hello' and hello['ball_script'] == {'seed': 3,
                                                                     'duration': 40.0}
        ball = next(r['facts'] for r in records if r['kind'] == 'model'
                    and r['facts']['name'] == 'ball')
        tracks.append(({r['t']: r['models']['ball'] for r in records if r['kind'] == 'state'},
                       ball['scripted']))
    (first, scripted), (second, scripted_again) = tracks
    assert scripted == scripted_again and scripted['seed'] == 3 and scripted['start'] == 0
    common = sorted(set(first) & set(second))
    assert len(common) > 150 and common[-1] > 15.0, common[-5:]
    for t in common:
        assert second[t] == pytest.approx(first[t], abs=1e-3), t
    assert any(first[t][2] == -3.0 for t in common) and any(first[t][2] == 0.5 for t in common)
    # the student's commands: answered with success, ignored, counted
    last = [r for r in pushed if r['kind'] == 'state'][-1]
    assert pushing['answers'] and all(pushing['answers'])
    assert last['ignored']['ball'] >= len(pushing['answers']) + 10
    assert 'ball' not in last.get('fed', {}) and 'ball' not in last.get('placed', {})
    # what the node publishes is the script's ball
    script = ball_script.from_legs(scripted['legs'], given={'duration': 40.0})
    for seen in (watched, pushing):
        assert len(seen['get']) >= 5 and len(seen['odom']) > 100 and len(seen['states']) > 50, \
            {key: len(value) for key, value in seen.items()}
        assert on_script(script, 0.0, seen['get']) == []
        assert on_script(script, 0.0, seen['odom']) == []
        # model_states has no stamp: it is read at the probe's last /clock, which may
        # be behind it (the probe's /clock queue, a thousand a second, fell 1 s and more
        # behind under CI's three test workers), never far ahead
        assert on_script(script, 0.0, seen['states'], before=0.5, after=5.0) == []

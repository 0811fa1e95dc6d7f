"""The simulator's side of a grader's run, with the real simulator node: what
it sends a grader about each model (its facts, the commands its drive took)
and the topics the profile records, a relative name following every model's
namespace (so a robot in /robot2 is recorded as the one in /robot). The
recording never changes what the student's commands do: a relay made before a
robot is spawned on its topic leaves that robot's drive as it was. Needs the
built workspace (tools/run test)."""
import os
import subprocess
import tempfile
import time

import pytest

from exp_assignment2.grading.run.truth import TruthServer, read_record
from test_launch_args import free_port, workspace_ready

pytestmark = pytest.mark.skipif(not workspace_ready(), reason='no catkin workspace')
HERE = os.path.dirname(os.path.abspath(__file__))


def wait_for(condition, timeout):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if condition():
            return True
        time.sleep(0.2)
    return False


def spawn_late_robot(env):
    """A robot spawned at run time into /late, as spawn_model does."""
    script = ('import rospy\nfrom gazebo_msgs.srv import SpawnModel\nfrom geometry_msgs.msg '
              'import Pose\nrospy.wait_for_service("/gazebo/spawn_urdf_model", 60)\n'
              'ok = rospy.ServiceProxy("/gazebo/spawn_urdf_model", SpawnModel)("late", '
              'open(%r).read(), "/late", Pose(), "world")\nprint(ok.success, ok.status_message)'
              % os.path.join(HERE, 'fixtures', 'spawned_robot.urdf'))
    return subprocess.run(['/usr/bin/python3', '-c', script], env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=90).stdout


def publish(env, topic):
    return subprocess.Popen(['rostopic', 'pub', '-r', '10', topic, 'geometry_msgs/Twist',
                             '{linear: {x: 0.3}}'], env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)


def test_the_simulator_tells_the_grader_what_each_model_is_and_who_drove_it(tmp_path):
    record = tmp_path / 'record'
    # a Unix socket's path is at most 108 bytes: pytest's tmp_path may be longer
    sock = os.path.join(tempfile.mkdtemp(prefix='exp2-link-'), 'truth.sock')
    server = TruthServer(sock, str(record), accept=lambda argv, executable: True)
    port = free_port()
    env = dict(os.environ, ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / 'log'),
               ROS_MASTER_URI='http://localhost:%d' % port, PYTHONUNBUFFERED='1',
               EXP2_GRADER_SOCKET=sock, EXP2_GRADER_TOPICS='cmd_vel,/late/cmd_vel')
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    launch = subprocess.Popen(['roslaunch', '-p', str(port), 'exp_assignment2',
                               'simulator.launch', 'camera_width:=240', 'robot_ns:=robot2'],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                              universal_newlines=True)
    output, said = '', ''
    try:
        if not wait_for(lambda: server.states > 20, 90):
            launch.terminate()
            output = launch.communicate(timeout=60)[0]
            raise AssertionError('no ground truth came: ' + output[-3000:])
        said = spawn_late_robot(env)      # after the relay on /late/cmd_vel was made
        pubs = [publish(env, '/robot2/cmd_vel'), publish(env, '/late/cmd_vel')]
        try:
            assert wait_for(lambda: server.topics >= 40, 60), 'too few commands relayed'
        finally:
            for pub in pubs:
                pub.terminate()
                pub.wait(10)
    finally:
        if launch.poll() is None:
            launch.terminate()
            output = launch.communicate(timeout=60)[0]
        server.close()
    assert said.startswith('True'), said
    found = read_record(str(record))
    robot = found.models['robot']
    assert robot['namespace'] == 'robot2'
    assert [p['command'] for p in robot['plugins'] if p.get('drive')] == ['/robot2/cmd_vel']
    assert any(s['type'] == 'camera' for s in robot['sensors'])
    assert robot['joints']['head_joint']['type'] == 'revolute'
    assert found.models['ball']['sphere'] == 0.5
    assert found.models['late']['namespace'] == 'late'
    for name in ('robot', 'late'):
        fed = [s.get('fed', {}).get(name, 0) for s in found.states]
        assert fed[-1] >= 10 and fed == sorted(fed), (name, fed[-5:])
    # the late robot drove: its drive took the commands the relay also took
    late = [s['models']['late'] for s in found.states if 'late' in s['models']]
    assert late[-1][0] - late[0][0] > 0.2, (late[0], late[-1])
    topics = {t for _, t, _ in found.topics}
    assert topics == {'/robot2/cmd_vel', '/late/cmd_vel'}, topics
    assert 'Traceback' not in output, output[-3000:]


def test_a_message_of_another_type_is_not_read_as_a_command():
    """Where a grader's relay took a topic first, what comes raw is read as the
    plugin's type only if it is that type: a TwistStamped read as a Twist would
    drive the robot at nonsense speeds; ROS would never have connected the two."""
    import io
    import rospy
    from geometry_msgs.msg import Twist, TwistStamped
    from exp_assignment2.sim.plugins.ros_io import read_as

    def raw(message):
        buff = io.BytesIO()
        message.serialize(buff)
        out = rospy.AnyMsg()
        out._buff = buff.getvalue()
        out._connection_header = {'type': message._type, 'md5sum': message._md5sum,
                                  'callerid': '/student'}
        return out
    command = Twist()
    command.linear.x = 0.3
    got = read_as(raw(command), Twist)
    assert got.linear.x == 0.3 and got._connection_header['callerid'] == '/student'
    stamped = TwistStamped()
    stamped.twist.linear.x = 0.3
    assert read_as(raw(stamped), Twist) is None
    broken = raw(command)
    broken._buff = b'\x01'
    assert read_as(broken, Twist) is None

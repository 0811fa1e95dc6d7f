"""smach_ros' IntrospectionClient of the original-code environment reads what its
IntrospectionServer publishes, and sets a machine's initial state through it, as
smach_ros' do (a ROS master of its own; smach_msgs from the workspace)."""
import os
import subprocess

import pytest

from original_env_helpers import PYTHON, original_env, run

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')

STUDENT = '''
import rospy, smach, smach_ros
rospy.init_node('student', disable_signals=True)

trail = []
class Say(smach.State):
    def __init__(self, outcome):
        smach.State.__init__(self, outcomes=['next', 'end'], input_keys=['note'])
        self.outcome = outcome
    def execute(self, ud):
        trail.append(ud.note)
        return self.outcome

sm = smach.StateMachine(outcomes=['end'])
sm.userdata.note = 'local'
with sm:
    smach.StateMachine.add('A', Say('next'), transitions={'next': 'B'})
    smach.StateMachine.add('B', Say('end'), transitions={'next': 'A'})
sis = smach_ros.IntrospectionServer('/patrol', sm, '/SM_ROOT')
sis.start()

client = smach_ros.IntrospectionClient()
deadline = rospy.get_time() + 30
while '/patrol' not in client.get_servers() and rospy.get_time() < deadline:
    rospy.sleep(0.1)
print('SERVERS', client.get_servers(), flush=True)
ud = smach.UserData()
ud.note = 'remote'
print('UNKNOWN', client.set_initial_state('/patrol', '/SM_ROOT', ['C'], ud,
                                          timeout=rospy.Duration(1.0)), flush=True)
print('NO WAIT', client.set_initial_state('/patrol', '/SM_ROOT', ['C'], ud), flush=True)
print('SET', client.set_initial_state('/patrol', '/SM_ROOT', ['B'], ud,
                                      timeout=rospy.Duration(30.0)), flush=True)
print('OUTCOME', sm.execute(), trail, flush=True)
sis.stop()
rospy.signal_shutdown('done')
'''


def test_the_client_finds_the_server_and_sets_the_initial_state(ros_master):
    try:
        proc = run(STUDENT, original_env(ros_master), timeout=120)
    except subprocess.TimeoutExpired as exc:
        pytest.fail('no end after 120 s:\n%s\n%s' % (exc.stdout, exc.stderr))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    # not rospy's lines (smach's start report goes on on a line of its own)
    said = [line for line in proc.stdout.splitlines() if not line.startswith(('[', '\t'))]
    assert said == ["SERVERS ['/patrol']", 'UNKNOWN False', 'NO WAIT None', 'SET True',
                    "OUTCOME end ['remote']"], proc.stdout + proc.stderr
    # the server refused the unknown state, as smach_ros' says
    assert "to '['C']', but this container only has states: ['A', 'B']" in proc.stderr

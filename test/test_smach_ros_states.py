"""tools/original_env's smach_ros: SimpleActionState, ServiceState and
MonitorState against a real action server, service and topic, in SMACH
containers, and a machine served by ActionServerWrapper, as a student's
state machine uses them (a ROS master of its own,
code run in the original-code environment)."""
import os
import subprocess

import pytest

from original_env_helpers import PYTHON, original_env, run

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')

# An action server (x > 0 succeeds, x < 0 aborts, x == 0 runs until cancelled),
# a SetBool service and an Int32 counter at 100 Hz; then the machines.
STUDENT = '''
import threading
import actionlib, rospy, smach, smach_ros
from exp_assignment2.msg import (PlanningAction, PlanningActionFeedback, PlanningFeedback,
                                 PlanningGoal, PlanningResult)
from std_msgs.msg import Int32
from std_srvs.srv import SetBool, SetBoolResponse

rospy.init_node('student', disable_signals=True)

def serve(goal):
    x = goal.target_pose.pose.position.x
    server.publish_feedback(PlanningFeedback(stat='started'))
    while x == 0 and not server.is_preempt_requested():
        rospy.sleep(0.01)
    if x > 0:
        server.set_succeeded(PlanningResult())
    elif x < 0:
        server.set_aborted(PlanningResult())
    else:
        server.set_preempted()
server = actionlib.SimpleActionServer('/robot/reaching_goal', PlanningAction, serve, False)
server.start()
rospy.Service('/switch', SetBool, lambda req: SetBoolResponse(True, 'got %s' % req.data))
counter = rospy.Publisher('/count', Int32, queue_size=10)
def count():
    n = 0
    while not rospy.is_shutdown():
        counter.publish(Int32(n))
        n += 1
        rospy.sleep(0.01)
threading.Thread(target=count, daemon=True).start()

@smach.cb_interface(input_keys=['x'])
def goal_cb(ud, goal):
    goal.target_pose.pose.position.x = ud.x
    return goal

heard = []
def goal_state():
    return smach_ros.SimpleActionState('/robot/reaching_goal', PlanningAction, goal_cb=goal_cb,
                                       result_key='result',
                                       feedback_cb=lambda ud, fb: heard.append(fb.stat))

@smach.cb_interface(output_keys=['said'], outcomes=['refused'])
def response_cb(ud, response):
    ud.said = response.message
    return None if response.success else 'refused'

sm = smach.StateMachine(outcomes=['done', 'failed'])
sm.userdata.x, sm.userdata.on, sm.userdata.wait = 1.0, True, 0.0
with sm:
    smach.StateMachine.add('GO', goal_state(), transitions={'succeeded': 'CALL',
                           'aborted': 'failed', 'preempted': 'failed'})
    smach.StateMachine.add('CALL', smach_ros.ServiceState('/switch', SetBool, request_slots=['data'],
                                                          response_cb=response_cb),
                           transitions={'succeeded': 'WATCH', 'aborted': 'failed',
                                        'preempted': 'failed', 'refused': 'failed'},
                           remapping={'data': 'on'})
    smach.StateMachine.add('WATCH', smach_ros.MonitorState('/count', Int32,
                                                           lambda ud, msg: msg.data < 30),
                           transitions={'invalid': 'BOTH', 'valid': 'failed',
                                        'preempted': 'failed'})
    both = smach.Concurrence(outcomes=['done', 'failed'], default_outcome='failed',
                             input_keys=['wait'],
                             child_termination_cb=lambda outcomes: outcomes['THREE'] == 'valid',
                             outcome_map={'done': {'THREE': 'valid', 'WAIT': 'preempted'}})
    smach.StateMachine.add('BOTH', both, transitions={'done': 'done', 'failed': 'failed'})
    with both:
        smach.Concurrence.add('WAIT', goal_state(), remapping={'x': 'wait'})
        smach.Concurrence.add('THREE', smach_ros.MonitorState('/count', Int32,
                                                              lambda ud, msg: True, max_checks=3))
trail = []
sm.register_transition_cb(lambda ud, active: trail.append(active[0]))
print('OUTCOME', sm.execute(), ' '.join(trail), sm.userdata.said,
      type(sm.userdata.result).__name__, heard[0], flush=True)

aborting = smach.StateMachine(outcomes=['aborted', 'other'])
aborting.userdata.x = -1.0
with aborting:
    smach.StateMachine.add('GO', goal_state(), transitions={'succeeded': 'other',
                           'preempted': 'other'})
print('ABORTED', aborting.execute(), flush=True)

# a machine as an action server: x > 0 succeeds at once, x == 0 waits on a
# silent topic until the goal is cancelled
@smach.cb_interface(input_keys=['action_goal'], output_keys=['action_feedback'],
                    outcomes=['go', 'wait'])
def look(ud):
    ud.action_feedback = PlanningFeedback(stat='looked')
    return 'go' if ud.action_goal.target_pose.pose.position.x > 0 else 'wait'
served = smach.StateMachine(outcomes=['done', 'stopped', 'broken'])
with served:
    smach.StateMachine.add('LOOK', smach.CBState(look), transitions={'go': 'done',
                                                                    'wait': 'WAIT'})
    smach.StateMachine.add('WAIT', smach_ros.MonitorState('/silent', Int32, lambda ud, m: True),
                           transitions={'valid': 'broken', 'invalid': 'broken',
                                        'preempted': 'stopped'})
smach_ros.ActionServerWrapper('/served', PlanningAction, served, succeeded_outcomes=['done'],
                              preempted_outcomes=['stopped']).run_server()
client = actionlib.SimpleActionClient('/served', PlanningAction)
assert client.wait_for_server(rospy.Duration(30))
# what the server says, from its topic: a SimpleActionClient drops feedback that
# comes before send_goal has stored the goal's handle, and LOOK answers at once
said = []
heard = rospy.Subscriber('/served/feedback', PlanningActionFeedback,
                         lambda m: said.append(m.feedback.stat))
while heard.get_num_connections() < 1:
    rospy.sleep(0.05)
goal = PlanningGoal()
goal.target_pose.pose.position.x = 1.0
client.send_goal(goal)
client.wait_for_result(rospy.Duration(30))
first = client.get_state()
goal.target_pose.pose.position.x = 0.0            # LOOK -> WAIT: a transition, so feedback
client.send_goal(goal)
rospy.sleep(1.0)
client.cancel_goal()
client.wait_for_result(rospy.Duration(30))
print('SERVED', first, client.get_state(), said[:1], flush=True)
rospy.signal_shutdown('done')
'''


def test_a_students_machine_of_action_service_and_monitor_states_runs(ros_master):
    try:
        proc = run(STUDENT, original_env(ros_master), timeout=180)
    except subprocess.TimeoutExpired as exc:       # where it stopped
        pytest.fail('no end after 180 s:\n%s\n%s' % (exc.stdout, exc.stderr))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    # not rospy's lines (smach's reports through it: a start report goes on on a second line)
    lines = [line for line in proc.stdout.splitlines() if not line.startswith(('[', '\t'))]
    assert lines[0].split() == ['OUTCOME', 'done', 'CALL', 'WATCH', 'BOTH', 'got', 'True',
                                'PlanningResult', 'started'], proc.stdout + proc.stderr
    assert lines[1] == 'ABORTED aborted'
    assert lines[2] == "SERVED 3 2 ['looked']"

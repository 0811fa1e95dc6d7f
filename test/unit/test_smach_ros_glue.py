"""smach_ros of the original-code environment, on small machines in Debian's python3
(no ROS master): what ``import smach_ros`` does to smach, set_preempt_handler and
ConditionState. IntrospectionClient, which needs a master, is in
test/test_smach_introspection.py."""
import os

import pytest

from original_env_helpers import PYTHON, base_env, original_env, run

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')

# A state that waits for its preempt, and says whether rospy was still up then.
WAITER = '''
import logging, threading, time
import rospy, smach, smach_ros

class Waiter(smach.State):
    def __init__(self):
        smach.State.__init__(self, outcomes=['preempted'])
        self.started = threading.Event()
    def execute(self, ud):
        self.started.set()
        deadline = time.monotonic() + 20
        while not self.preempt_requested() and time.monotonic() < deadline:
            time.sleep(0.01)
        print('PREEMPTED WITH ROSPY UP', not rospy.is_shutdown(), flush=True)
        time.sleep(0.3)                  # the handler waits for this too
        self.service_preempt()
        return 'preempted'

def machine(state):
    sm = smach.StateMachine(outcomes=['preempted'])
    with sm:
        smach.StateMachine.add('WAIT', state)
    return sm
'''


@pytest.fixture(scope='module')
def env():
    found = original_env(base_env())
    if 'smach_ros: shim' not in found['EXP2_ORIGINAL_ENV']:
        pytest.skip('a real smach_ros is installed here')
    return found


def lines(proc):
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return proc.stdout.splitlines()


def test_importing_smach_ros_hands_smachs_log_and_shutdown_to_rospy(env):
    proc = run('''
        import logging, smach
        smach.loginfo('before')             # printed, as SMACH's default
        import rospy, smach_ros
        print(smach.loginfo is rospy.loginfo, smach.logwarn is rospy.logwarn,
              smach.logdebug is rospy.logdebug, smach.logerr is rospy.logerr,
              smach.is_shutdown is rospy.is_shutdown)
        heard = []
        class Keep(logging.Handler):
            def emit(self, record):
                heard.append(record.getMessage())
        rosout = logging.getLogger('rosout')
        rosout.addHandler(Keep())
        rosout.setLevel(logging.INFO)
        sm = smach.StateMachine(outcomes=['end'])
        with sm:
            smach.StateMachine.add('ONLY', smach.CBState(lambda ud: 'end', outcomes=['end']))
        print(sm.execute(), heard[-1])
        rospy.signal_shutdown('test')
        print(smach.is_shutdown(), sm.execute())     # a machine no longer steps
    ''', env)
    assert lines(proc) == ['[  INFO ] : before', 'True True True True True',
                           "end State machine terminating 'ONLY':'end':'end'", 'True None']


def test_set_preempt_handler_preempts_the_machine_and_waits_for_it(env):
    proc = run(WAITER + '''
state = Waiter()
sm = machine(state)
smach_ros.set_preempt_handler(sm)
outcome = []
worker = threading.Thread(target=lambda: outcome.append(sm.execute()))
worker.start()
state.started.wait(10)
rospy.signal_shutdown('Ctrl-C')
print('SHUTDOWN RETURNED', outcome, sm.is_running(), flush=True)
''', env)
    assert lines(proc) == ['PREEMPTED WITH ROSPY UP True',
                           "SHUTDOWN RETURNED ['preempted'] False"]


def test_a_shutdown_from_the_machines_own_thread_does_not_hang(env):
    # a state that calls rospy.signal_shutdown itself (as a signal handler would run in
    # a node that calls sm.execute() in its main thread): the hook cannot wait there
    proc = run(WAITER + '''
class Quitter(smach.State):
    def __init__(self):
        smach.State.__init__(self, outcomes=['preempted', 'quit'])
    def execute(self, ud):
        rospy.signal_shutdown('done')
        return 'preempted' if self.preempt_requested() else 'quit'
sm = smach.StateMachine(outcomes=['preempted', 'quit'])
with sm:
    smach.StateMachine.add('QUIT', Quitter())
smach_ros.set_preempt_handler(sm)
print('OUTCOME', sm.execute())
''', env, timeout=30)
    assert lines(proc) == ['OUTCOME preempted']


CONDITION = '''
import rospy, smach, smach_ros
rospy.rostime.set_rostime_initialized(True)       # wall time: no node, no master
asked = []
def sequence(*answers):
    def cond(ud):
        asked.append(1)
        return answers[len(asked) - 1]
    return cond
def run(state, **ud):
    del asked[:]
    sm = smach.StateMachine(outcomes=['true', 'false', 'preempted'])
    sm.userdata.update(ud)
    with sm:
        smach.StateMachine.add('COND', state)
    start = rospy.get_time()
    outcome = sm.execute()
    return outcome, len(asked), rospy.get_time() - start
'''


def test_condition_state_polls_at_its_rate_until_true_or_its_checks_run_out(env):
    proc = run(CONDITION + '''
print(*run(smach_ros.ConditionState(sequence(False, False, True), poll_rate=0.1, max_checks=5)))
# max_checks=1, SMACH's default: asked twice, a sleep after each
print(*run(smach_ros.ConditionState(sequence(False, False, False),
                                    poll_rate=rospy.Duration(0.1))))
print(*run(smach_ros.ConditionState(sequence(*[False] * 100), poll_rate=0.05, max_checks=-1,
                                    timeout=rospy.Duration(0.3))))
''', env)
    found = [line.split() for line in lines(proc)]
    assert [words[:2] for words in found[:2]] == [['true', '3'], ['false', '2']]
    assert found[2][0] == 'false' and 2 <= int(found[2][1]) <= 8     # ~7 (fewer if slow)
    for words, least in zip(found, (0.2, 0.2, 0.3)):      # s: the sleeps between the asks
        assert least <= float(words[2]) < least + 2.0, words


def test_condition_state_preempts_reads_userdata_and_reports_a_broken_condition(env):
    proc = run(CONDITION + '''
@smach.cb_interface(input_keys=['battery'])
def charged(ud):
    return ud.battery > 50
print(run(smach_ros.ConditionState(charged), battery=80)[0],
      run(smach_ros.ConditionState(lambda ud: ud.level > 1, input_keys=['level']), level=0)[0])
early = smach_ros.ConditionState(lambda ud: True)
early.request_preempt()
print(run(early)[0], early.preempt_requested())
try:
    run(smach_ros.ConditionState(lambda ud: 1 / 0))
except smach.InvalidUserCodeError as exc:
    print('BROKEN', 'ZeroDivisionError' in str(exc))
''', env)
    assert lines(proc) == ['true false', 'preempted False', 'BROKEN True']

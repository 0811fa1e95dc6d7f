"""The original-code environment (src/exp_assignment2/original_env): the opt-in shell for code written for the original assignment.

The environment is built as tools/original_env/shell.sh builds it (environment.compute),
from the environment the tests run in, and used by subprocesses of Debian's
python3. No ROS master is needed. The cv2 GUI tests are in
test_original_env_gui.py.
"""
import os

import pytest

from original_env_helpers import ENV_DIR, PYTHON, base_env, original_env, run

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')


# Written as the original state_machine.py is (smach.State.__init__ with
# outcomes, `with sm:`, StateMachine.add with transitions, an introspection
# server, sm.execute()), plus userdata keys in the SMACH tutorial's style.
ORIGINAL_STYLE = '''
import smach
import smach_ros

class Normal(smach.State):
    def __init__(self):
        smach.State.__init__(self, outcomes=['outcome1', 'outcome2'],
                             input_keys=['normal_counter_in'], output_keys=['normal_counter_out'])
    def execute(self, userdata):
        count = userdata.normal_counter_in
        print('NORMAL', count)
        userdata.normal_counter_out = count + 1
        return 'outcome1' if count < 2 else 'outcome2'

class Sleep(smach.State):
    def __init__(self):
        smach.State.__init__(self, outcomes=['outcome1'])
    def execute(self, userdata):
        print('SLEEP')
        return 'outcome1'

sm = smach.StateMachine(outcomes=['outcome4'])
sm.userdata.sm_counter = 0
with sm:
    smach.StateMachine.add('NORMAL', Normal(),
                           transitions={'outcome1': 'SLEEP', 'outcome2': 'outcome4'},
                           remapping={'normal_counter_in': 'sm_counter',
                                      'normal_counter_out': 'sm_counter'})
    smach.StateMachine.add('SLEEP', Sleep(), transitions={'outcome1': 'NORMAL'})

sis = smach_ros.IntrospectionServer('server_name', sm, '/SM_ROOT')
sis.start()
outcome = sm.execute()
sis.stop()
print('OUTCOME', outcome, sm.userdata.sm_counter)
print('FILES', smach.__file__, smach_ros.__file__)
'''


def test_original_style_state_machine_runs_on_the_shims():
    env = original_env(base_env())
    proc = run(ORIGINAL_STYLE, env)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[:6] == ['NORMAL 0', 'SLEEP', 'NORMAL 1', 'SLEEP', 'NORMAL 2', 'OUTCOME outcome4 3']
    files = lines[6].split()[1:]
    assert all(f.startswith(os.path.join(ENV_DIR, 'shims')) for f in files), files
    assert 'smach: shim' in env['EXP2_ORIGINAL_ENV']


def test_nothing_leaks_into_the_default_environment():
    env = base_env()
    if run('import smach', env).returncode == 0:
        pytest.skip('a real smach is installed here')
    for module in ('smach', 'smach_ros'):
        proc = run('import %s' % module, env)
        assert proc.returncode != 0 and 'No module named' in proc.stderr
    proc = run('import sitecustomize; print(sitecustomize.__file__)', env)
    assert ENV_DIR not in proc.stdout


def test_a_real_smach_is_never_shadowed(tmp_path):
    real = tmp_path / 'smach'
    real.mkdir()
    (real / '__init__.py').write_text(
        'REAL = True\nclass StateMachine(object):\n    pass\n')
    env = original_env(base_env([str(tmp_path)]))
    assert os.path.join(ENV_DIR, 'shims', 'smach') not in env['PYTHONPATH'].split(os.pathsep)
    assert 'smach: installed one' in env['EXP2_ORIGINAL_ENV']
    proc = run('''
        import smach, smach_ros
        print(smach.REAL, smach.__file__)
        smach_ros.IntrospectionServer('x', smach.StateMachine(), '/SM_ROOT').start()
    ''', env)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.split() == ['True', str(real / '__init__.py')]

    # and a real smach_ros too
    (tmp_path / 'smach_ros').mkdir()
    (tmp_path / 'smach_ros' / '__init__.py').write_text('REAL = True\n')
    env = original_env(base_env([str(tmp_path)]))
    assert os.path.join(ENV_DIR, 'shims', 'smach_ros') not in env['PYTHONPATH'].split(os.pathsep)
    assert 'smach_ros: installed one' in env['EXP2_ORIGINAL_ENV']
    proc = run('import smach_ros; print(smach_ros.REAL)', env)
    assert proc.stdout.strip() == 'True', proc.stderr


def test_sitecustomize_runs_the_one_it_shadows_and_is_inert_without_display(tmp_path):
    (tmp_path / 'sitecustomize.py').write_text('import os\nos.environ["SHADOWED_RAN"] = "1"\n')
    env = original_env(base_env([str(tmp_path)]))
    proc = run('''
        import os, cv2
        print(os.environ.get("SHADOWED_RAN"), hasattr(cv2, "_exp2_gui_thread"))
    ''', env)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.split() == ['1', 'False']
    assert 'no DISPLAY' in env['EXP2_ORIGINAL_ENV']


XMLRPC_SHUTDOWN = '''
import os, time
import rosgraph.xmlrpc
threads = lambda: len(os.listdir('/proc/self/task'))
before = threads()
node = rosgraph.xmlrpc.XmlRpcNode(rpc_handler=rosgraph.xmlrpc.XmlRpcHandler())
node.start()
while node.uri is None:
    time.sleep(0.01)
node.shutdown('done')
cpu = time.process_time()
time.sleep(1.5)
print(threads() - before, round(time.process_time() - cpu, 2))
'''


def test_the_xml_rpc_thread_ends_at_shutdown_as_under_python_2():
    """Under Python 3, rospy's XML-RPC thread polls its closed socket at
    100 % of a core once the node shut down; in the shell it ends."""
    env = original_env(base_env())
    proc = run(XMLRPC_SHUTDOWN, env)
    assert proc.returncode == 0, proc.stderr
    left, cpu = proc.stdout.split()
    assert int(left) == 0 and float(cpu) < 0.2, proc.stdout
    # what it replaces: without it, the thread lives on (and spins, as
    # fast as a loaded machine lets it)
    proc = run(XMLRPC_SHUTDOWN, dict(env, EXP2_XMLRPC_END='0'))
    left, cpu = proc.stdout.split()
    assert int(left) == 1, proc.stdout

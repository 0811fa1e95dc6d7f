"""tools/original_env: the opt-in shell for code written for the original assignment.

The environment is built as tools/original_env/shell.sh builds it (env.py),
from the environment the tests run in, and used by subprocesses of Debian's
python3. No ROS master is needed. The GUI tests run on a private Xvfb and are
skipped when Xvfb is not installed.
"""
import json
import os
import queue
import select
import shutil
import subprocess
import textwrap
import threading
import time

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENV_DIR = os.path.join(REPO, 'tools', 'original_env')
PYTHON = '/usr/bin/python3'

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')


def base_env(pythonpath=()):
    """The environment outside the original-code shell (its entries removed)."""
    env = {k: v for k, v in os.environ.items() if k not in ('DISPLAY', 'EXP2_CV2_GUI_THREAD')}
    paths = [p for p in env.get('PYTHONPATH', '').split(os.pathsep)
             if p and not p.startswith(ENV_DIR)]
    # exp_assignment2 (for minismach): the sourced workspace, else src/.
    env['PYTHONPATH'] = os.pathsep.join(list(pythonpath) + paths + [os.path.join(REPO, 'src')])
    return env


def original_env(env):
    """What shell.sh sets, computed by the same helper."""
    out = subprocess.run([PYTHON, os.path.join(ENV_DIR, 'env.py'), '--json'], env=env,
                         stdout=subprocess.PIPE, universal_newlines=True, timeout=30, check=True)
    return dict(env, **json.loads(out.stdout))


def run(code, env, timeout=30):
    return subprocess.run([PYTHON, '-c', textwrap.dedent(code)], env=env, cwd='/',
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=timeout)


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


# --- cv2 HighGUI from several threads, on a private X server -----------------

@pytest.fixture(scope='module')
def xdisplay():
    if not shutil.which('Xvfb') or not shutil.which('xwininfo'):
        pytest.skip('Xvfb and xwininfo are not installed (apt-get install xvfb x11-utils)')
    read_fd, write_fd = os.pipe()
    # -displayfd: Xvfb picks a free display number and writes it when ready.
    server = subprocess.Popen(['Xvfb', '-displayfd', str(write_fd), '-screen', '0', '1024x768x24',
                               '-nolisten', 'tcp'], pass_fds=(write_fd,),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_fd)
    try:
        ready, _, _ = select.select([read_fd], [], [], 10)
        number = os.read(read_fd, 64).decode().strip() if ready else ''
        if not number:
            pytest.fail('Xvfb did not start')
        yield ':' + number
    finally:
        os.close(read_fd)
        server.terminate()
        server.wait(10)


def read_line(proc, deadline):
    """The next stdout line of proc, or '' when the deadline passes."""
    if not hasattr(proc, 'lines'):  # a thread reads stdout: select() misses buffered lines
        proc.lines = queue.Queue()
        threading.Thread(target=lambda: [proc.lines.put(line) for line in proc.stdout],
                         daemon=True).start()
    try:
        return proc.lines.get(timeout=max(0, deadline - time.monotonic())).strip()
    except queue.Empty:
        return ''


# Two threads, as two rospy subscriptions, each showing its own camera window.
TWO_CALLBACK_THREADS = '''
import sys, threading
import numpy as np, cv2
done = {}
def callback_thread(window, size):
    for i in range(30):
        frame = np.full((size, size, 3), (i * 8) % 256, np.uint8)
        cv2.circle(frame, (size // 2, size // 2), 5 + i, (0, 255, 0), -1)
        cv2.imshow(window, frame)
        cv2.waitKey(2)
        done[window] = i + 1
threads = [threading.Thread(target=callback_thread, args=(w, s), daemon=True)
           for w, s in (('cam_normal', 160), ('cam_play', 200))]
for t in threads:
    t.start()
for t in threads:
    t.join(15)
print('SHOWN', done.get('cam_normal'), done.get('cam_play'), flush=True)
sys.stdin.readline()  # windows stay up until the test has looked at them
print('EXIT', flush=True)
'''


def test_imshow_from_two_threads_does_not_hang(xdisplay):
    env = original_env(dict(base_env(), DISPLAY=xdisplay))
    assert 'one HighGUI thread' in env['EXP2_ORIGINAL_ENV']
    proc = subprocess.Popen([PYTHON, '-c', TWO_CALLBACK_THREADS], env=env, cwd='/',
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, universal_newlines=True)
    try:
        assert read_line(proc, time.monotonic() + 15) == 'SHOWN 30 30', 'imshow/waitKey hung'
        tree = ''
        for _ in range(20):  # the GUI thread maps the windows a few ms later
            tree = subprocess.run(['xwininfo', '-root', '-tree'], env=env, timeout=10,
                                  stdout=subprocess.PIPE, universal_newlines=True).stdout
            if '"cam_normal"' in tree and '"cam_play"' in tree:
                break
            time.sleep(0.1)
        assert '"cam_normal"' in tree and '"cam_play"' in tree, tree
        started = time.monotonic()
        proc.stdin.write('\n')
        proc.stdin.flush()
        assert read_line(proc, started + 10) == 'EXIT'
        proc.wait(10)  # the GUI thread must not keep the process alive
        assert proc.returncode == 0, proc.stderr.read()
        assert time.monotonic() - started < 5
    finally:
        proc.kill()
        proc.wait()


def test_single_threaded_use_and_keys(xdisplay):
    env = original_env(dict(base_env(), DISPLAY=xdisplay))
    proc = subprocess.Popen([PYTHON, '-c', textwrap.dedent('''
        import threading, numpy as np, cv2
        try:
            cv2.imshow('keys', None)
        except cv2.error:
            print('ERROR raised in the caller', flush=True)
        print('no window yet:', cv2.waitKey(0), flush=True)
        cv2.namedWindow('keys')
        cv2.imshow('keys', np.zeros((120, 120, 3), np.uint8))
        cv2.waitKey(50)
        print('visible:', cv2.getWindowProperty('keys', cv2.WND_PROP_VISIBLE), flush=True)
        print('READY', flush=True)
        result = []
        reader = threading.Thread(target=lambda: result.append(cv2.waitKey(8000)))
        reader.start()
        reader.join()
        print('KEY', result[0], flush=True)
        cv2.destroyAllWindows()
        print('after destroy:', cv2.waitKey(0), flush=True)
    ''')], env=env, cwd='/', stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        universal_newlines=True)
    try:
        deadline = time.monotonic() + 15
        assert read_line(proc, deadline) == 'ERROR raised in the caller'
        assert read_line(proc, deadline) == 'no window yet: -1'
        assert read_line(proc, deadline) == 'visible: 1.0'
        assert read_line(proc, deadline) == 'READY'
        if shutil.which('xdotool'):
            for _ in range(50):  # until the window is mapped and takes the focus
                window = subprocess.run(
                    ['xdotool', 'search', '--onlyvisible', '--name', '^keys$'], env=env,
                    timeout=10, stdout=subprocess.PIPE, universal_newlines=True).stdout.split()
                if window and subprocess.run(
                        ['xdotool', 'windowfocus', '--sync', window[0]], env=env, timeout=10,
                        stderr=subprocess.DEVNULL).returncode == 0:
                    break
                time.sleep(0.1)
            else:
                pytest.fail('could not focus the window "keys"')
            subprocess.run(['xdotool', 'key', 'a'], env=env, timeout=10, check=True)
            assert read_line(proc, deadline) == 'KEY 97'
        else:
            assert read_line(proc, deadline) == 'KEY -1'
        assert read_line(proc, deadline) == 'after destroy: -1'
        proc.wait(10)
        assert proc.returncode == 0, proc.stderr.read()
    finally:
        proc.kill()
        proc.wait()

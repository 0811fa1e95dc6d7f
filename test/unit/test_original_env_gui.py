"""The original-code environment: cv2 HighGUI from several threads, on a private X
server (skipped when Xvfb is not installed), as code written for the
original assignment calls it."""
import os
import queue
import select
import shutil
import subprocess
import textwrap
import threading
import time

import pytest

from original_env_helpers import PYTHON, base_env, original_env

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')


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
        tree, deadline = '', time.monotonic() + 10
        # the GUI thread maps the windows a few ms later; seconds on a loaded machine
        # (CI's three workers beside simulations: 2 s was once not enough)
        while time.monotonic() < deadline:
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

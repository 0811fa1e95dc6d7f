"""How nodes end (ros/ending.py): an error caused by the shutdown is dropped,
any other is raised, and the process leaves with the right code."""
import glob
import os
import signal
import socket
import subprocess
import sys
import threading
import time

import pytest

rospy = pytest.importorskip('rospy')
from exp_assignment2.ros import ending  # noqa: E402


REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


class Left(Exception):
    """Stands in for os._exit: carries the exit code."""


@pytest.fixture
def exits(monkeypatch):
    def fake_exit(code):
        raise Left(code)
    monkeypatch.setattr(ending.os, '_exit', fake_exit)


def leave_code(body):
    with pytest.raises(Left) as left:
        ending.run_until_shutdown(body)
    return left.value.args[0]


def fail():
    raise rospy.ROSException('topic was closed during publish()')


def test_a_body_that_returns_leaves_with_0(exits):
    assert leave_code(lambda: None) == 0


def test_an_error_during_shutdown_is_the_end_not_an_error(exits, monkeypatch):
    monkeypatch.setattr(ending.rospy.core, 'is_shutdown_requested', lambda: True)
    assert leave_code(fail) == 0


def test_an_error_while_running_is_raised(exits, monkeypatch):
    monkeypatch.setattr(ending.rospy.core, 'is_shutdown_requested', lambda: False)
    with pytest.raises(rospy.ROSException):
        ending.run_until_shutdown(fail)


def test_system_exit_keeps_its_code(exits):
    def stop():
        raise SystemExit(3)
    assert leave_code(stop) == 3


def test_a_start_interrupted_by_the_end_of_the_launch_leaves_with_0(exits, monkeypatch):
    def start():
        raise rospy.exceptions.ROSInitException('init_node interrupted before it could complete')
    monkeypatch.setattr(ending.rospy.core, 'is_shutdown_requested', lambda: True)
    assert leave_code(start) == 0


NODE_SCRIPTS = sorted(
    path for path in glob.glob(os.path.join(REPO, 'scripts', '*.py'))
    if 'rospy' in open(os.path.join(REPO, 'src', 'exp_assignment2', 'nodes',
                                    os.path.basename(path))).read())


def catches_sigint(pid):
    with open('/proc/%d/status' % pid) as f:
        mask = next(int(line.split()[1], 16) for line in f if line.startswith('SigCgt:'))
    return bool(mask & (1 << (signal.SIGINT - 1)))


class MissedPhase(Exception):
    """The poll did not see a phase of SIGINT's handling."""


def end_while_starting(script, phases, tmp_path, attempts=3):
    """Start ``script`` with no master, wait until SIGINT's handling has
    changed as ``phases`` says (Python's handler, the script's default, rospy's
    in init_node), send SIGINT: (exit code, output). The script's own phase
    lasts its imports, a few tenths of a second: a loaded machine kept the
    poll off its CPU for all of it once (the script then waited in init_node
    with rospy's handler), so a missed phase is tried again."""
    for attempt in range(attempts):
        try:
            return _end_while_starting(script, phases, tmp_path)
        except MissedPhase:
            if attempt == attempts - 1:
                raise


def _end_while_starting(script, phases, tmp_path):
    env = dict(os.environ, ROS_MASTER_URI='http://localhost:%d' % free_port(),
               ROS_HOME=str(tmp_path))
    # SIGINT at its default, as roslaunch starts a node: a test run started in
    # the background ignores it, and Python then never catches it
    proc = subprocess.Popen([sys.executable, script], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, env=env, universal_newlines=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        for caught in phases:
            deadline = time.monotonic() + 20.0
            while catches_sigint(proc.pid) != caught:
                assert proc.poll() is None, script
                if time.monotonic() > deadline:
                    raise MissedPhase('%s: SIGINT caught never became %s' % (script, caught))
                time.sleep(0.001)
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=30)
    finally:
        proc.kill()
    return proc.returncode, out


@pytest.mark.parametrize('script', NODE_SCRIPTS, ids=os.path.basename)
def test_a_node_ended_while_it_imports_ends_quietly(script, tmp_path):
    """roslaunch ends a launch (SIGINT) while a node still imports."""
    code, out = end_while_starting(script, (True, False), tmp_path)
    assert 'Traceback' not in out, out
    assert code == -signal.SIGINT, (code, out)


def messages_built():
    """The package's messages import (the catkin workspace is sourced)."""
    try:
        import exp_assignment2.msg  # noqa: F401
    except ImportError:
        return False
    return True


@pytest.mark.skipif(not messages_built(),
                    reason='the node reaches init_node only with the messages built: '
                           'bash tools/run setup')
def test_a_node_ended_in_init_node_ends_quietly(tmp_path):
    """... or waits in init_node for its master: rospy's handler has it."""
    script = os.path.join(REPO, 'scripts', 'state_machine.py')
    code, out = end_while_starting(script, (True, False, True), tmp_path)
    assert 'Traceback' not in out, out
    assert code == 0, (code, out)


@pytest.fixture
def deferred(monkeypatch):
    """A DeferredShutdown whose signal_shutdown is recorded; the process's
    handlers are put back afterwards."""
    calls = []
    lock = threading.Lock()

    def signal_shutdown(reason):
        with lock:      # as closing a publisher takes its queue's lock
            calls.append(reason)
    monkeypatch.setattr(ending.rospy.core, 'signal_shutdown', signal_shutdown)
    saved = {sig: signal.getsignal(sig) for sig in ending.DeferredShutdown.SIGNALS}
    shutdown = ending.DeferredShutdown()
    shutdown.register()
    yield shutdown, lock, calls
    for sig, handler in saved.items():
        signal.signal(sig, handler)


def test_a_signal_in_a_frame_holding_a_lock_shuts_down_once_the_frame_lets_go(deferred):
    """rospy's own handler would close publishers inside the interrupted
    frame, which holds one's lock: the node hung until SIGKILL."""
    shutdown, lock, calls = deferred
    with lock:      # a publish from the main thread
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(0.2)     # the handler has run, in this frame
        assert calls == [] and not shutdown.done.is_set()
    shutdown.wait(5.0)
    assert calls == ['signal-%d' % signal.SIGINT]


def test_sigterm_shuts_down_with_rospys_reason(deferred):
    shutdown, _, calls = deferred
    os.kill(os.getpid(), signal.SIGTERM)
    shutdown.wait(5.0)
    assert calls == ['signal-%d' % signal.SIGTERM]


def test_without_a_signal_leaving_does_not_wait(deferred):
    shutdown, _, _ = deferred
    start = time.monotonic()
    shutdown.wait(5.0)
    assert time.monotonic() - start < 1.0

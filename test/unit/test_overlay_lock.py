"""One build of an overlay at a time (original_env/overlay/lock.py): a second
builder waits for the first, says so, and gives up after its time with the
reason a person can act on. No ROS, no build."""
import fcntl
import os
import signal
import threading
import time

import pytest

from exp_assignment2.original_env.overlay import build
from exp_assignment2.original_env.overlay.lock import Locked


def hold(path):
    """Another builder's hold on the lock (flock is per open file)."""
    other = open(path, 'w')
    fcntl.flock(other, fcntl.LOCK_EX)
    return other


def test_a_free_lock_is_taken_at_once_without_a_word(tmp_path):
    said = []
    with Locked(str(tmp_path / 'overlay' / '.lock'), 5, said.append):
        assert os.path.exists(tmp_path / 'overlay' / '.lock')
    assert said == []


def test_a_held_lock_is_waited_for_and_taken_when_the_other_lets_go(tmp_path):
    path = str(tmp_path / '.lock')
    other, said = hold(path), []
    releaser = threading.Timer(0.3, other.close)
    releaser.start()
    start = time.monotonic()
    with Locked(path, 5, said.append):
        waited = time.monotonic() - start
    releaser.join()
    assert waited >= 0.25
    assert said == ['waiting for another build of this overlay (at most 5 s)']
    assert signal.alarm(0) == 0     # no alarm left behind


def test_a_lock_held_too_long_gives_up_with_the_reason_and_restores_the_alarm(tmp_path):
    path = str(tmp_path / '.lock')
    other = hold(path)
    before = signal.getsignal(signal.SIGALRM)
    try:
        with pytest.raises(TimeoutError, match='another build of this overlay held it for 1 s'):
            with Locked(path, 1):
                pass
    finally:
        other.close()
    assert signal.getsignal(signal.SIGALRM) is before
    assert signal.alarm(0) == 0


def test_the_build_says_which_package_waited_too_long(tmp_path, monkeypatch):
    package = tmp_path / 'pkg'
    package.mkdir()
    (package / 'package.xml').write_text(
        '<package format="2"><name>pkg</name><version>0.0.0</version><description>d'
        '</description><maintainer email="teacher@example.com">a</maintainer><license>MIT</license>'
        '</package>')

    def locked(path, timeout, waiting):
        raise TimeoutError('another build of this overlay held it for %d s' % timeout)
    monkeypatch.setattr(build, 'Locked', locked)
    with pytest.raises(build.BuildFailed) as failed:
        build.build(str(package), workspace=str(tmp_path / 'ws'), root=str(tmp_path / 'ov'),
                    environ={})
    assert str(failed.value) == ('the build of %s failed: another build of this overlay held'
                                 ' it for %d s' % (os.path.realpath(package), build.LOCK_TIMEOUT))

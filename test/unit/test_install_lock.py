"""tools/install.sh: installers started at once take turns (on a fresh
machine the test workers open the original environment together, and every
apt-get but one failed on dpkg's lock)."""
import os
import subprocess
import time

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
INSTALL = os.path.join(REPO, 'tools', 'install.sh')

# what an installer does while it holds the lock, made slow enough to overlap
HOLDER = '''
source "%s"
work() { echo "start $1" >> "$LOG"; sleep 0.3; echo "end $1" >> "$LOG"; }
_with_install_lock work "$1"
''' % INSTALL


def test_installers_started_at_once_take_turns(tmp_path):
    log = tmp_path / 'log'
    env = dict(os.environ, LOG=str(log), TMPDIR=str(tmp_path))
    procs = [subprocess.Popen(['bash', '-c', HOLDER, 'holder', str(i)], env=env)
             for i in range(3)]
    assert [p.wait(20) for p in procs] == [0, 0, 0]
    events = log.read_text().splitlines()
    assert len(events) == 6
    for start, end in zip(events[0::2], events[1::2]):      # never interleaved
        assert start.startswith('start ') and end == 'end ' + start.split()[1], events


def test_what_is_installed_is_not_installed_again(tmp_path):
    # dpkg itself is always installed: no apt-get, no lock, no output
    out = subprocess.run(['bash', '-c', 'source "%s"; install_debian test dpkg' % INSTALL],
                         capture_output=True, text=True, timeout=30,
                         env=dict(os.environ, TMPDIR=str(tmp_path)))
    assert out.returncode == 0 and out.stderr == '', out.stderr
    assert not (tmp_path / 'exp_assignment2-install.lock').exists()


@pytest.mark.skipif(os.geteuid() != 0, reason='install_debian runs apt-get through sudo')
def test_what_is_missing_is_installed_under_errexit_and_pipefail(tmp_path):
    """The callers (tools/run, shell.sh) run with ``set -eo pipefail``, which
    the lock's process substitution inherits: dpkg-query's exit status for a
    package it does not know once made the list empty, and nothing was
    installed. apt-get is a fake here that says what it was asked."""
    fake = tmp_path / 'bin' / 'apt-get'
    fake.parent.mkdir()
    fake.write_text('#!/bin/sh\necho "apt-get $*" >> "%s"\n' % (tmp_path / 'asked'))
    fake.chmod(0o755)
    script = 'set -eo pipefail; source "%s"; install_debian test dpkg exp2-no-such-package' % (
        INSTALL)
    env = dict(os.environ, TMPDIR=str(tmp_path), PATH='%s:%s' % (fake.parent, os.environ['PATH']))
    out = subprocess.run(['bash', '-c', script], capture_output=True, text=True, timeout=30,
                         env=env)
    assert out.returncode == 0, out.stderr
    assert '[test] installing Debian packages: exp2-no-such-package' in out.stderr
    asked = (tmp_path / 'asked').read_text().splitlines()
    assert asked[-1].endswith('install -y -qq exp2-no-such-package'), asked


def test_the_overlay_build_takes_the_same_lock(tmp_path, monkeypatch):
    """debian_packages.install (the overlay build's dev packages) waits for
    an installer of tools/install.sh, then asks again what is missing."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(
        'debian_packages', os.path.join(REPO, 'src', 'exp_assignment2', 'original_env',
                                        'overlay', 'debian_packages.py'))
    debian_packages = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(debian_packages)
    log = tmp_path / 'log'
    monkeypatch.setattr(debian_packages, 'LOCK', str(tmp_path / 'exp_assignment2-install.lock'))
    holder = subprocess.Popen(['bash', '-c', HOLDER, 'holder', 'shell'],
                              env=dict(os.environ, LOG=str(log), TMPDIR=str(tmp_path)))
    try:
        deadline = time.monotonic() + 20.0
        while not log.exists():         # the shell's installer holds the lock
            assert time.monotonic() < deadline, 'the holder never took the lock'
            time.sleep(0.01)
        asked = []
        monkeypatch.setattr(debian_packages, 'missing',
                            lambda packages: asked.append(log.read_text()) or ['libfoo-dev'])

        def apt_install(needed):
            with log.open('a') as f:
                f.write('apt-get %s\n' % needed[0])
        monkeypatch.setattr(debian_packages, '_apt_install', apt_install)
        debian_packages.install(['libfoo-dev'])
        assert holder.wait(20) == 0
    finally:
        if holder.poll() is None:
            holder.kill()
    assert log.read_text().splitlines() == ['start shell', 'end shell', 'apt-get libfoo-dev']
    assert asked[-1] == 'start shell\nend shell\n'      # asked again once the lock was free

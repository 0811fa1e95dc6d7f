"""The package is well-formed as catkin sees it (workspace path, named
exp_assignment2): catkin_lint -W2 --strict reports nothing."""
import os
import shutil
import subprocess

import pytest


def package_dir():
    try:
        out = subprocess.run(['rospack', 'find', 'exp_assignment2'], stdout=subprocess.PIPE,
                             universal_newlines=True, timeout=30)
    except FileNotFoundError:
        return None
    return out.stdout.strip() or None


@pytest.mark.skipif(shutil.which('catkin_lint') is None, reason='catkin_lint not installed')
def test_catkin_lint_is_clean():
    path = package_dir()
    if not path:    # tools/run test always has one; a bare pytest run may not
        pytest.skip('no catkin workspace: rospack cannot find exp_assignment2')
    assert os.path.basename(path) == 'exp_assignment2'
    proc = subprocess.run(['catkin_lint', '-W2', '--strict', path], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=120)
    problems = [l for l in proc.stdout.splitlines() if 'error' in l or 'warning' in l]
    assert proc.returncode == 0 and not problems, proc.stdout


def test_the_workspace_keeps_roslaunch_off_setuptools_distutils():
    """The env hook (env-hooks/): with the workspace sourced, roslaunch's
    import (rosclean's ``import distutils``) does not load setuptools'
    copy and pkg_resources, and a value the user set is kept."""
    ws = os.environ.get('EXP2_WS') or os.path.expanduser('~/.cache/exp_assignment2_ws')
    setup = os.path.join(ws, 'devel', 'setup.bash')
    if not os.path.exists(setup):
        pytest.skip('no catkin workspace at %s' % ws)
    probe = ('/usr/bin/python3 -c "import sys, roslaunch; '
             'print(\'pkg_resources\' in sys.modules)"; echo $SETUPTOOLS_USE_DISTUTILS')

    def run(env):
        return subprocess.run(['bash', '-c', 'source %s && %s' % (setup, probe)],
                              stdout=subprocess.PIPE, universal_newlines=True, env=env,
                              timeout=60).stdout.split()
    env = {k: v for k, v in os.environ.items() if k != 'SETUPTOOLS_USE_DISTUTILS'}
    assert run(env) == ['False', 'stdlib']
    assert run(dict(env, SETUPTOOLS_USE_DISTUTILS='local')) == ['True', 'local']

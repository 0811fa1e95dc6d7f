"""Python 2's tab rule in the original-code shell, every way a script starts.

The shell is tools/original_env/shell.sh (what ``bash tools/run original-env``
runs after the set-up) on the workspace this test runs in: the one sourced
(tools/run test sources it), never another. The fixture node (test/original_tabs/tabs_node.py, which imports
tabs_helper.py; both mix tabs and spaces as original student code does) is
put in a catkin-less ROS package on ROS_PACKAGE_PATH, then started in one
original-code shell as ``python3 x.py``, ``python x.py``, ``./x.py``,
``rosrun`` and ``roslaunch`` (which starts its own master on a free port). Each
must print what Python 2 would have printed, and the one stderr line naming
the two files.
"""
import os
import shutil
import socket
import subprocess

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIXTURES = os.path.join(REPO, 'test', 'original_tabs')
LINE = "[original-env] read with Python 2's tab rule: "
NODE_OUTPUT = ['count 33', 'tally 202',
               "strings ('a\\tb', '\\tsecond line, after a tab in the string', 92)"]

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="2">
  <name>tabs_fixture</name>
  <version>0.0.0</version>
  <description>Original-style code mixing tabs and spaces (test fixture).</description>
  <maintainer email="nobody@example.com">nobody</maintainer>
  <license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
'''
LAUNCH = '''<launch>
  <node name="tabs_node" pkg="tabs_fixture" type="tabs_node.py" args="way roslaunch"
        output="screen" required="true"/>
</launch>
'''
WAYS = ('python3', 'python', './', 'rosrun', 'roslaunch')


def sourced_workspace():
    """The catkin workspace whose devel space is sourced here, or None."""
    for prefix in os.environ.get('CMAKE_PREFIX_PATH', '').split(os.pathsep):
        if os.path.basename(prefix) == 'devel' and os.path.isfile(
                os.path.join(prefix, 'setup.bash')):
            workspace = os.path.dirname(prefix)
            if os.path.exists(os.path.join(workspace, 'src', 'exp_assignment2')):
                return workspace
    return None


def run_in_original_env(script, tmp_path, workspace, timeout=300):
    """A bash script run in the original-code shell (its ROS_HOME in tmp_path)."""
    env = dict(os.environ, ROS_HOME=str(tmp_path / 'ros_home'), PYTHONUNBUFFERED='1',
               EXP2_WS=workspace)
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    return subprocess.run(['bash', os.path.join(REPO, 'tools', 'original_env', 'shell.sh'),
                           'bash', '-c', script], env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=timeout)


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


@pytest.fixture
def package(tmp_path):
    root = tmp_path / 'packages'
    scripts = root / 'tabs_fixture' / 'scripts'
    shutil.copytree(FIXTURES, str(scripts))
    (scripts / 'tabs_node.py').chmod(0o755)
    (root / 'tabs_fixture' / 'package.xml').write_text(PACKAGE_XML)
    (root / 'tabs_fixture' / 'launch').mkdir()
    (root / 'tabs_fixture' / 'launch' / 'tabs.launch').write_text(LAUNCH)
    return root


@pytest.mark.skipif(shutil.which('rosrun', path='/usr/bin') is None, reason='needs ROS')
def test_every_way_of_starting_reads_python2s_indentation(package, tmp_path):
    workspace = sourced_workspace()
    if workspace is None:
        pytest.skip('no sourced catkin workspace (run it through tools/run test)')
    port = free_port()
    script = '\n'.join([
        'export ROS_PACKAGE_PATH=%s:$ROS_PACKAGE_PATH' % package,
        'export ROS_MASTER_URI=http://localhost:%d' % port,
        'cd %s' % (package / 'tabs_fixture' / 'scripts'),
        'echo "== python3"; python3 tabs_node.py way python3 2>&1',
        'echo "== python"; python tabs_node.py way python 2>&1',
        'echo "== ./"; ./tabs_node.py way ./ 2>&1',
        'echo "== rosrun"; rosrun tabs_fixture tabs_node.py way rosrun 2>&1',
        'echo "== roslaunch"; roslaunch -p %d tabs_fixture tabs.launch 2>&1' % port,
    ])
    proc = run_in_original_env(script, tmp_path, workspace)
    assert proc.returncode == 0, proc.stdout[-3000:]
    sections, name = {}, None
    for line in proc.stdout.splitlines():
        if line.startswith('== '):
            name = line[3:]
            sections[name] = []
        elif name:
            sections[name].append(line)
    assert sorted(sections) == sorted(WAYS), proc.stdout[-3000:]
    scripts = package / 'tabs_fixture' / 'scripts'
    for way in WAYS:
        lines = sections[way]
        output = [line for line in lines if line in NODE_OUTPUT or line.startswith('argv ')]
        assert output[:3] == NODE_OUTPUT, (way, lines)
        assert output[3].startswith('argv way ' + way), (way, lines)
        reports = [line for line in lines if line.startswith(LINE)]
        # roslaunch starts nodes in ROS_HOME: the names are then absolute
        named = ('tabs_node.py, tabs_helper.py' if way != 'roslaunch' else
                 '%s, %s' % (scripts / 'tabs_node.py', scripts / 'tabs_helper.py'))
        assert reports == [LINE + named], (way, lines)
        assert not [line for line in lines if 'Error' in line], (way, lines)
    assert 'process has finished cleanly' in '\n'.join(sections['roslaunch'])

"""A Python 2 node in the original-code shell, started by roslaunch and by rosrun.

The shell is tools/original_env/shell.sh on the workspace this test runs in (tools/run
test sources it). The node is the course's kind: ``#!/usr/bin/env python``, print
statements, a Python 2 helper module, integer division, a rospy timer, and
``raw_input`` asking for a command, with standard input at /dev/null (as the grader
starts commands). roslaunch (its own master on a free port, ``output="screen"``) runs it
with one line to type (EXP2_KEYBOARD, by node name); then rosrun starts a second one
beside it, with another. Each must print what Python 2 printed, get its line at its
time, then wait for the keyboard while its timer goes on, until SIGINT (rospy's
shutdown) ends it.
"""
import os
import shutil
import signal
import socket
import subprocess

import pytest

from test_original_env_tabs import REPO, sourced_workspace

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="2">
  <name>py2_fixture</name>
  <version>0.0.0</version>
  <description>Original-style Python 2 code (test fixture).</description>
  <maintainer email="nobody@example.com">nobody</maintainer>
  <license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
'''
LAUNCH = '''<launch>
  <node name="asker" pkg="py2_fixture" type="asker.py" output="screen"/>
</launch>
'''
HELPER = '''def half(n):
    print "half of", n
    return n / 2
'''
NODE = '''#!/usr/bin/env python
import rospy
import helper

def tick(event):
    print "tick", rospy.get_name()

rospy.init_node('asker')
print "Reached", helper.half(7), 7.0 / 2
rospy.Timer(rospy.Duration(0.5), tick)
while not rospy.is_shutdown():
    command = raw_input("Command: (m)ove ball, (d)isappear ball: ")
    print "got", command, "in", rospy.get_name()
'''
READ = '[original-env] read as Python 2 (translated in memory): '
WAITED = '[original-env] waited for keyboard input at scripts/asker.py:12'
PROMPT = 'Command: (m)ove ball, (d)isappear ball: '


def run_in_original_env(script, tmp_path, workspace, timeout=300):
    """A bash script run in the original-code shell, with Ctrl-C's signal as a terminal
    gives it (a test runner's worker may ignore it, and ignored it stays in children)."""
    env = dict(os.environ, ROS_HOME=str(tmp_path / 'ros_home'), PYTHONUNBUFFERED='1',
               EXP2_WS=workspace)
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    return subprocess.run(['bash', os.path.join(REPO, 'tools', 'original_env', 'shell.sh'),
                           'bash', '-c', script], env=env, stdin=subprocess.DEVNULL,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=timeout,
                          preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


def left_running(marker):
    """Processes whose command line names ``marker``, as (pid, command)."""
    found = []
    for pid in filter(str.isdigit, os.listdir('/proc')):
        try:
            with open('/proc/%s/cmdline' % pid, 'rb') as f:
                command = f.read().replace(b'\0', b' ').decode(errors='replace')
        except OSError:
            continue
        if marker in command:
            found.append((int(pid), command))
    return found


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


@pytest.fixture
def package(tmp_path):
    root = tmp_path / 'packages'
    scripts = root / 'py2_fixture' / 'scripts'
    scripts.mkdir(parents=True)
    (scripts / 'asker.py').write_text(NODE)
    (scripts / 'asker.py').chmod(0o755)
    (scripts / 'helper.py').write_text(HELPER)
    (root / 'py2_fixture' / 'package.xml').write_text(PACKAGE_XML)
    (root / 'py2_fixture' / 'launch').mkdir()
    (root / 'py2_fixture' / 'launch' / 'py2.launch').write_text(LAUNCH)
    return root


@pytest.mark.skipif(shutil.which('rosrun', path='/usr/bin') is None, reason='needs ROS')
def test_a_python2_node_runs_and_waits_for_the_keyboard(package, tmp_path):
    workspace = sourced_workspace()
    if workspace is None:
        pytest.skip('no sourced catkin workspace (run it through tools/run test)')
    port = free_port()
    out = tmp_path / 'launch.out'
    script = '\n'.join([
        'set -m',       # roslaunch in the background gets SIGINT too (as Ctrl-C would)
        'export ROS_PACKAGE_PATH=%s:$ROS_PACKAGE_PATH' % package,
        'export ROS_MASTER_URI=http://localhost:%d' % port,
        """EXP2_KEYBOARD='{"asker": [{"at": 1, "text": "m"}]}' timeout -k 20 -s INT 40 \\""",
        '  roslaunch -p %d py2_fixture py2.launch </dev/null >%s 2>&1 & launched=$!' % (port, out),
        'for i in $(seq 60); do grep -q "^tick /asker" %s && break; sleep 0.5; done' % out,
        """EXP2_KEYBOARD='[{"at": 1, "text": "d"}]' timeout -k 3 -s INT 8 \\""",
        '  rosrun py2_fixture asker.py __name:=second </dev/null 2>&1',
        'kill -INT $launched; wait',
        'echo "== roslaunch"; cat %s' % out,
    ])
    proc = run_in_original_env(script, tmp_path, workspace)
    stray = left_running(str(package))
    for pid, _ in stray:
        os.kill(pid, signal.SIGKILL)
    assert stray == [], 'left running after SIGINT'
    rosrun, _, launched = proc.stdout.partition('== roslaunch\n')
    for lines, name, typed, read in (
            (launched.splitlines(), '/asker', 'm', READ + '%s, %s' % (
                package / 'py2_fixture' / 'scripts' / 'asker.py',
                package / 'py2_fixture' / 'scripts' / 'helper.py')),
            (rosrun.splitlines(), '/second', 'd', READ + '%s, %s' % (
                package / 'py2_fixture' / 'scripts' / 'asker.py',
                package / 'py2_fixture' / 'scripts' / 'helper.py'))):
        assert read in lines, lines
        assert lines[lines.index('half of 7') + 1] == 'Reached 3 3.5', lines
        # typed at 1 s (echoed after the prompt, maybe after a tick: a terminal's order)
        got = lines.index('got %s in %s' % (typed, name))
        assert lines[got - 1] in (typed, PROMPT + typed), lines
        waited = lines.index(WAITED)            # then asked again: nobody types
        assert waited > got and PROMPT in '\n'.join(lines[got:waited]), lines
        assert ('tick ' + name) in lines[waited + 1:], lines    # its timer goes on
        assert not [line for line in lines if 'Error' in line], lines
    # stopping it shuts rospy down, which ends the wait: no need for SIGTERM
    assert 'escalating to SIGTERM' not in launched, launched
    assert proc.returncode == 0, proc.stdout[-3000:]

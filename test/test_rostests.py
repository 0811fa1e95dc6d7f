"""Runs every rostest launch file in test/ (each starts its own master).

The ones the turn sign changes run once per robot model
(``robot_model:=rep103`` and ``original``). A launch file that says
``<!-- run in original-env -->`` (code written for the original, with its
smach, tabs and Python 2 habits) runs inside ``tools/original_env/shell.sh``,
as a user would run it. They run one after another in each pytest-xdist
worker (tools/run test runs three); the simulator runs as fast as it can in
each, up to 20x. A failing rostest shows the checks that failed and the tail
of its output here. A node of this package that roslaunch has to SIGTERM at
the end fails its rostest too.
"""
import glob
import os
import re
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
# run against a system that test_student_package.py launches, not on its own
NOT_ALONE = ('student_package.test',)
TESTS = sorted(os.path.basename(t) for t in glob.glob(os.path.join(HERE, '*.test'))
               if os.path.basename(t) not in NOT_ALONE)
# what the turn sign changes: driving, following the ball, the play around it
# (dog_sleep and dog_preempt add nothing turn-related to these and the
# original_* tests, and run once)
BOTH_MODELS = ('simulator.test', 'dog_play.test', 'robot_to_ball.test')
ORIGINAL_ENV_MARK = '<!-- run in original-env -->'
SHELL = os.path.join(os.path.dirname(HERE), 'tools', 'original_env', 'shell.sh')
SCRIPTS = os.listdir(os.path.join(os.path.dirname(HERE), 'scripts'))
CASES = [(t, []) for t in TESTS] + [(t, ['robot_model:=original']) for t in TESTS
                                    if t in BOTH_MODELS]


def failures(output):
    """The unittest blocks of the checks that failed (FAIL: or ERROR: up to the
    next rule), which the output's tail may have left out."""
    lines, keep, out = output.splitlines(), False, []
    for line in lines:
        if line.startswith(('FAIL: ', 'ERROR: ')):
            keep = True
        elif line.startswith('-' * 20) and keep and out and out[-1].strip() == '':
            keep = False
        if keep:
            out.append(line)
    return out[:80] + (['...'] if out else [])


def stubborn_nodes(log_dir):
    """This package's nodes that roslaunch had to SIGTERM at the end of the
    run, from rostest's log. Code written for the original (under test/) may
    go on after SIGINT, as rospy lets it; ours must not."""
    exe, stubborn = {}, []
    for path in glob.glob(os.path.join(log_dir, 'rostest-*.log')):
        with open(path, errors='replace') as f:
            for line in f:
                started = re.search(r"process\[(\S+)\]: args\[\['([^']+)'", line)
                if started:
                    exe[started.group(1)] = started.group(2)
                escalated = re.search(r'\[(\S+)\] escalating to SIGTERM', line)
                if escalated:
                    stubborn.append(escalated.group(1))
    return [name for name in stubborn
            if os.path.basename(exe.get(name, '')) in SCRIPTS
            and '/test/' not in exe.get(name, '')]


@pytest.mark.parametrize('launch,args', CASES,
                         ids=[' '.join([t] + a) for t, a in CASES])
def test_rostest(launch, args, tmp_path):
    env = dict(os.environ, ROS_HOME=str(tmp_path), ROS_LOG_DIR=str(tmp_path / 'log'),
               PYTHONUNBUFFERED='1')
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    command = ['rostest', '--text', 'exp_assignment2', launch] + args
    with open(os.path.join(HERE, launch)) as f:
        if ORIGINAL_ENV_MARK in f.read():
            command = ['bash', SHELL] + command
    proc = subprocess.run(command,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                          timeout=600, universal_newlines=True)
    tail = '\n'.join(failures(proc.stdout) + proc.stdout.splitlines()[-60:])
    assert proc.returncode == 0, 'rostest %s failed:\n%s' % (' '.join([launch] + args), tail)
    assert 'SUMMARY' in proc.stdout and 'RESULT: SUCCESS' in proc.stdout, tail
    stubborn = stubborn_nodes(env['ROS_LOG_DIR'])
    assert not stubborn, 'still running 15 s after SIGINT at the end: %s' % stubborn

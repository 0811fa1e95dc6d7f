"""Node files as they reach a teacher, started by roslaunch and rosrun in the
original-code shell as the students' machines started them.

The fixture package (test/fixtures/handed_in_pkg, copied and put on
ROS_PACKAGE_PATH) has a script whose first line is ``#! /usr/bin/python``, one
with ``#!/usr/bin/env python2`` and one without its execute bit. Each must run
on /usr/bin/python3 (through the shell's python), with one stderr line naming
the file that had no execute bit, and no file's mode changed. The shell is
tools/original_env/shell.sh on the sourced workspace (tools/run test sources it).
"""
import os
import shutil

import pytest

from test_original_env_tabs import free_port, run_in_original_env, sourced_workspace

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIXTURE = os.path.join(REPO, 'test', 'fixtures', 'handed_in_pkg')
MODES = {'usr_bin_python.py': 0o755, 'env_python2.py': 0o755, 'lost_exec_bit.py': 0o644}
NOT_EXECUTABLE = '[original-env] not executable, started as if it were (the files are not changed): '


@pytest.fixture
def package(tmp_path):
    root = tmp_path / 'packages'
    shutil.copytree(FIXTURE, str(root / 'handed_in_pkg'))
    for name, mode in MODES.items():
        (root / 'handed_in_pkg' / 'scripts' / name).chmod(mode)
    return root


@pytest.mark.skipif(shutil.which('rosrun', path='/usr/bin') is None, reason='needs ROS')
def test_python2_first_lines_and_lost_execute_bits_start_as_on_the_students_machines(
        package, tmp_path):
    workspace = sourced_workspace()
    if workspace is None:
        pytest.skip('no sourced catkin workspace (run it through tools/run test)')
    port = free_port()
    marks = tmp_path / 'marks'
    marks.mkdir()
    script = '\n'.join([
        'export ROS_PACKAGE_PATH=%s:$ROS_PACKAGE_PATH' % package,
        'export ROS_MASTER_URI=http://localhost:%d' % port,
        'echo "== rosrun"',
        'rosrun handed_in_pkg usr_bin_python.py %s 2>&1' % marks,
        'rosrun handed_in_pkg lost_exec_bit.py %s 2>&1' % marks,
        'echo "== roslaunch"; rm -f %s/*' % marks,
        'roslaunch -p %d handed_in_pkg handed_in.launch marks:=%s 2>&1' % (port, marks),
    ])
    proc = run_in_original_env(script, tmp_path, workspace)
    out = proc.stdout
    assert proc.returncode == 0, out[-3000:]
    rosrun, roslaunch = out.split('== rosrun\n', 1)[1].split('== roslaunch\n', 1)
    scripts = package / 'handed_in_pkg' / 'scripts'
    lost = str(scripts / 'lost_exec_bit.py')
    for section, names in ((rosrun, ('usr_bin_python', 'lost_exec_bit')),
                           (roslaunch, ('usr_bin_python', 'env_python2', 'lost_exec_bit'))):
        for name in names:
            assert 'node %s ran on /usr/bin/python3, its file mode %o' % (
                name, MODES[name + '.py']) in section, section[-3000:]
        assert [line for line in section.splitlines() if line.startswith('[original-env] not')] \
            == [NOT_EXECUTABLE + lost], section[-3000:]
        assert 'No such file or directory' not in section and 'ERROR' not in section, section
    assert 'process has finished cleanly' in roslaunch
    for name, mode in MODES.items():
        assert (scripts / name).stat().st_mode & 0o777 == mode

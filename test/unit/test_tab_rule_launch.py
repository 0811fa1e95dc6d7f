"""Python 2's tab rule of the original-code shell, in real interpreters (no ROS master).

The shell's environment is made as shell.sh makes it: environment.compute's variables and
a bin directory with ``python`` and ``python3``, copies of
src/exp_assignment2/original_env/programs/python_launcher.sh.
The fixtures (test/original_tabs: a script and the module it imports, both
mixing tabs and spaces) are copied to a temporary directory and started the
ways a user starts them; test/test_original_env_tabs.py adds rosrun and
roslaunch inside ``tools/run original-env``.
"""
import hashlib
import os
import shutil
import subprocess

import pytest

from exp_assignment2.original_env.environment import compute

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENV_DIR = os.path.join(REPO, 'src', 'exp_assignment2', 'original_env')
FIXTURES = os.path.join(REPO, 'test', 'original_tabs')
PYTHON = '/usr/bin/python3'
LINE = "[original-env] read with Python 2's tab rule: "
NODE_OUTPUT = ['count 33', 'tally 202',
               "strings ('a\\tb', '\\tsecond line, after a tab in the string', 92)"]

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')


@pytest.fixture
def shell(tmp_path):
    """(environment, directory with the fixtures) of the original-code shell."""
    bin_dir, work = tmp_path / 'bin', tmp_path / 'work'
    bin_dir.mkdir()
    for name in ('python', 'python3'):
        shutil.copy(os.path.join(ENV_DIR, 'programs', 'python_launcher.sh'), str(bin_dir / name))
        (bin_dir / name).chmod(0o755)
    shutil.copytree(FIXTURES, str(work))
    (work / 'tabs_node.py').chmod(0o755)
    drop = ('DISPLAY', 'EXP2_TAB_RULE', 'PYTHONDONTWRITEBYTECODE', 'PYTHONSTARTUP')
    env = {k: v for k, v in os.environ.items() if k not in drop}
    paths = [p for p in env.get('PYTHONPATH', '').split(os.pathsep)
             if p and not p.startswith(ENV_DIR)]
    env['PYTHONPATH'] = os.pathsep.join(paths + [os.path.join(REPO, 'src')])
    env['EXP2_ORIGINAL_BIN'] = str(bin_dir)
    return dict(env, **compute(env)), work


def run(args, env, cwd, stdin=None):
    return subprocess.run(args, env=env, cwd=str(cwd), input=stdin, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, timeout=60)


def digest(directory):
    return {name: hashlib.sha1((directory / name).read_bytes()).hexdigest()
            for name in ('tabs_node.py', 'tabs_helper.py')}


@pytest.mark.parametrize('command', [['python3', 'tabs_node.py'], ['python', 'tabs_node.py'],
                                     ['./tabs_node.py']], ids=' '.join)
def test_the_fixture_runs_as_python2_indented_it(shell, command):
    env, work = shell
    before = digest(work)
    proc = run(command + ['a', 'b'], env, work)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == NODE_OUTPUT + ['argv a b']
    assert proc.stderr == LINE + 'tabs_node.py, tabs_helper.py\n'
    merged = subprocess.run(command, env=dict(env, PYTHONUNBUFFERED='1'), cwd=str(work),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=60).stdout.splitlines()
    assert merged[:2] == [LINE + 'tabs_node.py, tabs_helper.py', 'count 33']  # line first
    assert digest(work) == before  # the files on disk are never changed
    # no bytecode of the re-indented source (a module Python 3 reads gets its own),
    # so python3 outside the shell (-E: without its PYTHONPATH) still sees the real file
    (work / 'clean.py').write_text('X = 1\n')
    assert run(['python3', '-c', 'import clean, tabs_helper'], env, work).returncode == 0
    cached = os.listdir(str(work / '__pycache__'))
    assert [n.split('.')[0] for n in cached] == ['clean']
    plain = run([PYTHON, '-E', '-c', 'import tabs_helper'], env, work)
    assert plain.stderr.rstrip().endswith(
        'TabError: inconsistent use of tabs and spaces in indentation'), plain.stderr


def test_python3_accepts_it_so_it_runs_exactly_as_it_is(shell):
    env, work = shell
    probe = ('"""Probe."""\nimport sys\nprint(sys.argv, __file__, sys.path[0], __doc__)\n'
             'print(sorted(k for k in globals()), type(__loader__).__name__, __spec__,\n'
             '      __cached__, type(__builtins__).__name__, __name__, sys.orig_argv[1:],\n'
             '      sys.flags.optimize, __debug__)\n')
    (work / 'sub').mkdir()
    (work / 'sub' / 'spaces.py').write_text(probe)
    (work / 'sub' / 'tabs.py').write_text(probe + 'if True:\n\tprint("tabs only")\n')
    os.symlink('sub/tabs.py', str(work / 'link.py'))
    for script in ('sub/spaces.py', 'sub/tabs.py', 'link.py', str(work / 'sub' / 'tabs.py')):
        for options in ([], ['-O']):
            ours = run(['python3'] + options + [script, 'x'], env, work)
            real = run([PYTHON] + options + [script, 'x'], env, work)
            assert ours.returncode == real.returncode == 0, ours.stderr
            assert (ours.stdout, ours.stderr) == (real.stdout, real.stderr) == (real.stdout, '')


def test_other_uses_of_the_interpreter_are_the_interpreters(shell):
    env, work = shell
    code = 'import tabs_helper; print(tabs_helper.tally("xyz"))'
    assert run(['python3', '-c', code], env, work).stdout == '303\n'  # imported: tab rule
    assert run(['python3'], env, work, stdin=code).stdout == '303\n'
    assert run(['python3', '-'], env, work, stdin=code).stdout == '303\n'
    assert run(['python3', '-u', '-W', 'ignore', '-m', 'tabs_node'], env,
               work).stdout.splitlines() == NODE_OUTPUT + ['argv ']
    # a script read from a pipe is read by the interpreter only
    assert run(['bash', '-c', 'python3 <(echo "print(7)")'], env, work).stdout == '7\n'
    version = run(['python3', '--version'], env, work)
    assert version.stdout == run([PYTHON, '--version'], env, work).stdout
    assert run(['python3', '-Wignore', '-X', 'utf8', '--', 'tabs_node.py', '-c'], env,
               work).stdout.splitlines() == NODE_OUTPUT + ['argv -c']
    # -E drops PYTHONPATH (the shell with it), EXP2_TAB_RULE=0 the tab rule: Python 3's TabError
    assert 'TabError' in run(['python3', '-E', 'tabs_node.py'], env, work).stderr
    off = dict(env, EXP2_TAB_RULE='0')
    assert 'TabError' in run(['python3', 'tabs_node.py'], off, work).stderr
    assert 'TabError' in run(['python3', '-c', 'import tabs_helper'], off, work).stderr


@pytest.mark.parametrize('how', ['script', 'module'])
def test_what_python2_could_not_indent_fails_with_its_error(shell, how):
    env, work = shell
    (work / 'bad.py').write_text('def f():\n        x = 1\n\tif x:\n\t\ty = 2\n    return 3\n')
    (work / 'uses_bad.py').write_text('import bad\n')
    proc = run(['python3', 'bad.py' if how == 'script' else 'uses_bad.py'], env, work)
    assert proc.returncode == 1
    assert 'File "%s", line 5\n    return 3\n' % (work / 'bad.py') in proc.stderr
    assert proc.stderr.rstrip().endswith(
        'IndentationError: unindent does not match any outer indentation level')
    assert 'exp2_' not in proc.stderr and LINE not in proc.stderr


def test_tracebacks_show_the_real_lines_and_columns(shell):
    env, work = shell
    (work / 'caret.py').write_text(
        'import tabs_helper\ndef g():\n    if True:\n\treturn 1 + tabs_helper.fail()\n'
        '        pass\ng()\n')
    proc = run(['python3', 'caret.py'], env, work)
    assert proc.returncode == 1
    lines = proc.stderr.splitlines()
    assert lines[0] == LINE + 'caret.py, tabs_helper.py'
    assert lines[1] == 'Traceback (most recent call last):'
    assert lines[2].endswith('caret.py", line 6, in <module>')
    at = lines.index('    return 1 + tabs_helper.fail()')
    assert lines[at - 1].endswith('caret.py", line 4, in g')
    carets = lines[at + 1]
    assert lines[at][carets.index('^'):len(carets)] == 'tabs_helper.fail()'
    assert lines[at + 2].endswith('tabs_helper.py", line 27, in fail')
    assert lines[at + 3] == '    raise ValueError("raised on line 27")'
    assert lines[-1] == 'ValueError: raised on line 27'
    assert 'exp2_' not in proc.stderr and '<string>' not in proc.stderr


def test_exit_status_and_interrupt_as_python(shell):
    env, work = shell
    (work / 'leave.py').write_text('import sys\nif 1:\n\tsys.exit(4)\n        pass\n')
    assert run(['python3', 'leave.py'], env, work).returncode == 4
    (work / 'stop.py').write_text('if 1:\n\traise KeyboardInterrupt\n        pass\n')
    proc = run(['python3', 'stop.py'], env, work)
    assert proc.returncode == -2  # killed by SIGINT, as Python does
    assert proc.stderr.rstrip().endswith('KeyboardInterrupt')


def test_one_line_per_burst_of_imports(shell):
    env, work = shell
    shutil.copy(str(work / 'tabs_helper.py'), str(work / 'other_helper.py'))
    (work / 'main_spaces.py').write_text(
        '"""No tabs here."""\nimport sys\nimport tabs_helper\nimport json\n'
        'import other_helper\nprint("imported")\n\n\ndef later():\n'
        '    import tabs_node\n\n\nlater()\nprint("done")\n')
    proc = run(['python3', 'main_spaces.py'], env, work)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr.splitlines() == [LINE + 'tabs_helper.py, other_helper.py',
                                        LINE + 'tabs_node.py']
    # written before the program goes on: with python -u the order is visible
    merged = subprocess.run(['python3', '-u', 'main_spaces.py'], env=env, cwd=str(work),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=60).stdout.splitlines()
    assert merged == [LINE + 'tabs_helper.py, other_helper.py', 'imported',
                      LINE + 'tabs_node.py', 'done']


CATKIN_RELAY_TEMPLATE = '/usr/share/catkin/cmake/templates/script.py.in'


@pytest.mark.skipif(not os.path.exists(CATKIN_RELAY_TEMPLATE), reason='needs catkin')
def test_catkin_relay_scripts_compile_with_the_tab_rule(shell):
    """What catkin_install_python puts in a devel space, and rosrun/roslaunch start there."""
    env, work = shell
    with open(CATKIN_RELAY_TEMPLATE) as f:
        relay = f.read().replace('@PYTHON_EXECUTABLE@', PYTHON).replace(
            '@PYTHON_SCRIPT@', str(work / 'tabs_node.py'))
    (work / 'devel').mkdir()
    (work / 'devel' / 'tabs_node.py').write_text(relay)
    (work / 'devel' / 'tabs_node.py').chmod(0o755)
    env = dict(env, PYTHONPATH=str(work) + os.pathsep + env['PYTHONPATH'])  # for tabs_helper
    proc = subprocess.run([str(work / 'devel' / 'tabs_node.py'), 'relayed'],
                          env=dict(env, PYTHONUNBUFFERED='1'), cwd=str(work / 'devel'),
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=60)
    assert proc.returncode == 0, proc.stdout
    assert proc.stdout.splitlines() == [  # the line comes first, before the node's output
        LINE + '%s, %s' % (work / 'tabs_node.py', work / 'tabs_helper.py')] + NODE_OUTPUT + [
        'argv relayed']
    (work / 'bad.py').write_text('if 1:\n\tx = 1\n    y = 2\n')
    relay = relay.replace(str(work / 'tabs_node.py'), str(work / 'bad.py'))
    (work / 'devel' / 'tabs_node.py').write_text(relay)
    proc = run([str(work / 'devel' / 'tabs_node.py')], env, work)
    assert 'File "%s", line 3' % (work / 'bad.py') in proc.stderr
    assert proc.stderr.rstrip().endswith(
        'IndentationError: unindent does not match any outer indentation level')


def test_this_repositorys_own_scripts_start_as_they_are(shell):
    """The launcher leaves this repository's scripts (the simulator, also as
    exp_assignment2_sim) to /usr/bin/python3 as they are: the grader knows its
    simulator by that command line. Seen with the fixture folder as EXP2_REPO:
    its tabs are then Python 3's to refuse."""
    env, work = shell
    proc = run(['python3', 'tabs_node.py'], dict(env, EXP2_REPO=str(work)), work)
    assert proc.returncode != 0 and 'TabError' in proc.stderr
    assert run(['python3', 'tabs_node.py'], env, work).returncode == 0

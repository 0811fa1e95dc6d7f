"""Python 2 code in the original-code shell, in real interpreters (no ROS master).

The shell's environment is made as shell.sh makes it: environment.compute's variables and
a bin directory with ``python`` and ``python3``, copies of programs/python_launcher.sh.
A Python 2 node and module are written to a temporary directory and started the ways a
user starts them; test/test_original_env_py2.py adds rosrun and roslaunch.
"""
import hashlib
import os
import shutil
import subprocess

import pytest

from exp_assignment2.original_env.environment import compute

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENV_DIR = os.path.join(REPO, 'src', 'exp_assignment2', 'original_env')
PYTHON = '/usr/bin/python3'
LINE = '[original-env] read as Python 2 (translated in memory): '
HELPER = '''def half(n):
    return n / 2


def table(d):
    for k, v in sorted(d.iteritems()):
        print k, v
    return d.has_key('a')
'''
NODE = '''#!/usr/bin/env python
import sys
import helper
print "Reached", helper.half(7), 7.0 / 2
print helper.table({'a': 1})
print "argv", " ".join(sys.argv[1:])
'''
NODE_OUTPUT = ['Reached 3 3.5', 'a 1', 'True']

pytestmark = pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')


@pytest.fixture
def shell(tmp_path):
    """(environment, directory with the node) of the original-code shell."""
    bin_dir, work = tmp_path / 'bin', tmp_path / 'work'
    bin_dir.mkdir()
    work.mkdir()
    for name in ('python', 'python3'):
        shutil.copy(os.path.join(ENV_DIR, 'programs', 'python_launcher.sh'), str(bin_dir / name))
        (bin_dir / name).chmod(0o755)
    (work / 'helper.py').write_text(HELPER)
    (work / 'node.py').write_text(NODE)
    (work / 'node.py').chmod(0o755)
    drop = ('DISPLAY', 'EXP2_TAB_RULE', 'EXP2_PY2', 'PYTHONDONTWRITEBYTECODE', 'PYTHONSTARTUP')
    env = {k: v for k, v in os.environ.items() if k not in drop}
    paths = [p for p in env.get('PYTHONPATH', '').split(os.pathsep)
             if p and not p.startswith(ENV_DIR)]
    env['PYTHONPATH'] = os.pathsep.join(paths + [os.path.join(REPO, 'src')])
    env['EXP2_ORIGINAL_BIN'] = str(bin_dir)
    env = dict(env, **compute(env))
    env['PATH'] = str(bin_dir) + os.pathsep + env['PATH']
    return env, work


def run(args, env, cwd):
    return subprocess.run(args, env=env, cwd=str(cwd), stdin=subprocess.DEVNULL,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=60)


def digest(directory):
    return {p.name: hashlib.sha1(p.read_bytes()).hexdigest() for p in directory.glob('*.py')}


@pytest.mark.parametrize('command', [['python3', 'node.py'], ['python', 'node.py'],
                                     ['./node.py']], ids=' '.join)
def test_a_python2_node_runs_as_python2_ran_it(shell, command):
    env, work = shell
    before = digest(work)
    proc = run(command + ['a', 'b'], env, work)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == NODE_OUTPUT + ['argv a b']
    assert proc.stderr == LINE + 'node.py, helper.py\n'
    assert digest(work) == before                           # the files are never changed
    assert not (work / '__pycache__').exists() or not [     # nor compiled beside them
        n for n in os.listdir(str(work / '__pycache__')) if n.startswith('helper')]


def test_a_python2_module_imported_by_a_python3_node(shell):
    env, work = shell
    (work / 'node3.py').write_text('import helper\nprint(helper.half(9), helper.table({}))\n')
    proc = run(['python3', 'node3.py'], env, work)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == '4 False\n'
    assert proc.stderr == LINE + 'helper.py\n'


def test_python3_code_is_run_as_it_is(shell):
    env, work = shell
    (work / 'own.py').write_text('def raw_input(p):\n    return "mine"\n'
                                 'print(raw_input("x"), 7 / 2)\n')
    proc = run(['python3', 'own.py'], env, work)
    assert (proc.returncode, proc.stdout, proc.stderr) == (0, 'mine 3.5\n', '')


def test_tracebacks_name_the_students_lines(shell):
    env, work = shell
    (work / 'crash.py').write_text(
        'from urllib import urlencode, quote\nimport sys\ntry:\n    raise ValueError(1, 2)\n'
        'except ValueError, (a, b):\n    print >>sys.stderr, "caught", a, b\n'
        'def go(n):\n\tif n:\n\t    return helper.half(n) / 0\nimport helper\ngo(3)\n')
    proc = run(['python3', 'crash.py'], env, work)
    assert proc.returncode == 1
    lines = proc.stderr.splitlines()
    # helper.py, imported after the first statements, gets a line of its own
    assert lines[:3] == [LINE + 'crash.py', 'caught 1 2', LINE + 'helper.py']
    assert lines[3] == 'Traceback (most recent call last):'
    assert lines[4].endswith('crash.py", line 11, in <module>') and lines[5] == '    go(3)'
    assert lines[6].endswith('crash.py", line 9, in go')
    assert lines[7] == '    return helper.half(n) / 0'
    # the line the file has, with no marks under it: they would point into the translation
    assert lines[8:] == ['ZeroDivisionError: integer division or modulo by zero']
    assert 'exp2_' not in proc.stderr


def test_a_node_python3_refuses_for_a_late_global_runs_with_python2s_warning(shell):
    """Written as Python 3 but for a ``global`` after the assignment: Melodic ran it."""
    env, work = shell
    (work / 'late.py').write_text(
        'count = 0\ndef on_message(n):\n    count = n\n    global count\n    return count\n'
        'print(on_message(4), count)\n')
    proc = run(['python3', 'late.py'], env, work)
    assert (proc.returncode, proc.stdout) == (0, '(4, 4)\n'), proc.stderr
    assert proc.stderr.splitlines() == [
        "%s:4: SyntaxWarning: name 'count' is assigned to before global declaration"
        % (work / 'late.py'), '  global count', LINE + 'late.py']


def test_a_file_neither_python_reads_fails_on_its_line(shell):
    env, work = shell
    (work / 'bad.py').write_text('import sys\nprint "a"\ndef f(a, a):\n    pass\n')
    (work / 'uses_bad.py').write_text('import bad\n')
    for script in ('bad.py', 'uses_bad.py'):
        proc = run(['python3', script], env, work)
        assert proc.returncode == 1
        assert 'File "%s", line 3\n' % (work / 'bad.py') in proc.stderr
        assert proc.stderr.rstrip().endswith(
            "SyntaxError: duplicate argument 'a' in function definition")
        assert 'exp2_' not in proc.stderr and LINE not in proc.stderr


def test_bytecode_a_plain_python3_cached_is_not_used_for_python2_code(shell):
    env, work = shell
    (work / 'asks.py').write_text('def ask():\n    return raw_input("? ")\n')
    assert run([PYTHON, '-E', '-c', 'import asks'], env, work).returncode == 0
    assert [n for n in os.listdir(str(work / '__pycache__')) if n.startswith('asks')]
    proc = run(['python3', '-c', 'import asks; print(asks.ask.__code__.co_names)'], env, work)
    assert proc.stdout == "('input',)\n" and proc.stderr == LINE + 'asks.py\n'


def test_switched_off_python2_code_fails_as_in_python3(shell):
    env, work = shell
    proc = run(['python3', 'node.py'], dict(env, EXP2_PY2='0'), work)
    assert proc.returncode == 1 and 'SyntaxError' in proc.stderr


CATKIN_RELAY_TEMPLATE = '/usr/share/catkin/cmake/templates/script.py.in'


@pytest.mark.skipif(not os.path.exists(CATKIN_RELAY_TEMPLATE), reason='needs catkin')
def test_catkin_relay_scripts_read_python2(shell):
    """What catkin_install_python puts in a devel space, and rosrun/roslaunch start there."""
    env, work = shell
    with open(CATKIN_RELAY_TEMPLATE) as f:
        relay = f.read().replace('@PYTHON_EXECUTABLE@', PYTHON).replace(
            '@PYTHON_SCRIPT@', str(work / 'node.py'))
    (work / 'devel').mkdir()
    (work / 'devel' / 'node.py').write_text(relay)
    (work / 'devel' / 'node.py').chmod(0o755)
    env = dict(env, PYTHONPATH=str(work) + os.pathsep + env['PYTHONPATH'])  # for helper
    for command in ([str(work / 'devel' / 'node.py'), 'relayed'],
                    ['python3', str(work / 'devel' / 'node.py'), 'relayed']):
        proc = run(command, env, work / 'devel')
        assert proc.returncode == 0, proc.stderr
        assert proc.stdout.splitlines() == NODE_OUTPUT + ['argv relayed']
        assert proc.stderr == LINE + '%s, %s\n' % (work / 'node.py', work / 'helper.py')


def test_a_package_module_imports_its_sibling_as_python2_did(shell):
    """Python 2's implicit relative import: ``import b`` in package ``pkg`` found pkg/b.py."""
    env, work = shell
    (work / 'pkg').mkdir()
    (work / 'pkg' / '__init__.py').write_text('')
    (work / 'pkg' / 'a.py').write_text('import b\nprint "a sees", b.NAME\n')
    (work / 'pkg' / 'b.py').write_text('NAME = "pkg.b"\n')
    proc = run(['python3', '-c', 'import pkg.a'], env, work)
    assert (proc.returncode, proc.stdout) == (0, 'a sees pkg.b\n'), proc.stderr


def test_without_fissix_the_standard_librarys_2to3_translates(shell):
    """fissix caches its grammar in the user's cache: where it cannot, lib2to3 does the work."""
    env, work = shell
    code = 'import exp2_py2_translate as t; print(t.BACKEND); import helper; helper.table({})'
    proc = run(['python3', '-c', code], dict(env, XDG_CACHE_HOME='/proc/no-cache'), work)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0] == 'lib2to3' and proc.stderr == LINE + 'helper.py\n'

"""The terminal programs of the original-code environment
(original_env/programs/terminal.py, written as gnome-terminal, xterm, konsole,
terminator): their arguments read as each program reads them, then, on a
private X server with Debian's xterm (skipped without them), a window opened
for each whose command's output also reaches the opener's standard output."""
import importlib.util
import os
import shutil
import subprocess
import sys
import time

import pytest

from exp_assignment2.original_env import environment

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_original_env_gui import xdisplay  # noqa: E402,F401  (the fixture)

PROGRAM = os.path.join(environment.PROGRAMS, 'terminal.py')
spec = importlib.util.spec_from_file_location('terminal_program', PROGRAM)
terminal = importlib.util.module_from_spec(spec)
spec.loader.exec_module(terminal)


def windows(name, *args):
    found, wait = terminal.parse(name, list(args))
    return [(w.command, w.title, w.geometry, w.cwd) for w in found], wait


def test_gnome_terminal_reads_its_own_argument_forms_and_returns_at_once():
    assert windows('gnome-terminal', '-x', 'sh', '-c', 'roslaunch p a.launch; bash') == (
        [(['sh', '-c', 'roslaunch p a.launch; bash'], None, None, None)], False)
    assert windows('gnome-terminal', '--', 'rosrun', 'p', 'n.py') == (
        [(['rosrun', 'p', 'n.py'], None, None, None)], False)
    assert windows('gnome-terminal', '-e', 'rosrun p "my node.py"', '--title=T') == (
        [(['rosrun', 'p', 'my node.py'], 'T', None, None)], False)
    # a tab each, their titles and commands; a title before the first tab is its own
    assert windows('gnome-terminal', '--tab', '--title', 'world', '-e', 'roslaunch p w.launch',
                   '--tab', '-tdog', '--command=rosrun p dog.py')[0] == [
        (['roslaunch', 'p', 'w.launch'], 'world', None, None),
        (['rosrun', 'p', 'dog.py'], 'dog', None, None)]
    assert windows('gnome-terminal', '--title', 'x', '--window', '--geometry=80x24+0+0',
                   '--working-directory', '/w', '--hide-menubar', '--profile', 'P', '--wait',
                   '--', 'top') == ([(['top'], 'x', '80x24+0+0', '/w')], True)
    assert windows('gnome-terminal') == ([(None, None, None, None)], False)    # a shell
    for bad, said in ((['--bogus'], 'unknown option --bogus'), (['--'], '-- needs a command'),
                      (['-e', 'sh -c "x'], 'cannot read the command'),
                      (['--title'], 'option --title needs a value')):
        with pytest.raises(terminal.Usage, match=said):
            terminal.parse('gnome-terminal', bad)


def test_xterm_konsole_and_terminator_wait_for_their_command():
    found, wait = terminal.parse('xterm', ['-hold', '-geometry', '80x20', '-e', 'dog.py', 'x'])
    assert (found[0].options, found[0].command, wait) == (['-hold', '-geometry', '80x20'],
                                                           ['dog.py', 'x'], True)
    with pytest.raises(terminal.Usage, match='-e requires a command'):
        terminal.parse('xterm', ['-e'])
    assert windows('konsole', '--hold', '-p', 'tabtitle=dog', '-e', 'rosrun', 'p', 'n') == (
        [(['rosrun', 'p', 'n'], 'dog', None, None)], True)
    assert windows('terminator', '-T', 'ball', '-x', 'rosrun', 'p', 'b') == (
        [(['rosrun', 'p', 'b'], 'ball', None, None)], True)
    assert windows('terminator', '-u', '--command=rosrun p b')[0][0][0] == ['rosrun', 'p', 'b']


def test_the_real_xterm_runs_the_relay_under_the_title_xterm_would_give():
    window = terminal.parse('xterm', ['-e', '/w/src/scripts/dog.py', '__name:=dog'])[0][0]
    argv = terminal.xterm_argv('/usr/bin/xterm', window, 5, 7)
    assert argv[:3] == ['/usr/bin/xterm', '-T', 'dog.py']
    assert argv[argv.index('-e') + 1:] == [sys.executable, os.path.realpath(PROGRAM),
                                           terminal.RELAY, '5', '7', '--',
                                           '/w/src/scripts/dog.py', '__name:=dog']
    titled = terminal.parse('xterm', ['-T', 'mine', '-e', 'top'])[0][0]
    assert terminal.xterm_argv('/usr/bin/xterm', titled, -1, 3).count('-T') == 1


@pytest.fixture()
def programs(tmp_path):
    if not shutil.which('xterm', path='/usr/bin'):
        pytest.skip("Debian's xterm is not installed (tools/run grade installs it)")
    environment.write_programs(str(tmp_path), str(tmp_path))
    return tmp_path


def window_titles(display):
    tree = subprocess.run(['xwininfo', '-root', '-children'], env=dict(os.environ,
                          DISPLAY=display), stdout=subprocess.PIPE, universal_newlines=True)
    return [line.split('"')[1] for line in tree.stdout.splitlines() if line.count('"') >= 2]


def run(programs, display, argv, out, **kwargs):
    env = dict(os.environ, DISPLAY=display, PATH='%s:/usr/bin:/bin' % programs)
    with open(str(out), 'wb') as log:
        return subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=env, **kwargs)


def test_a_window_of_each_its_output_also_in_the_log(programs, xdisplay, tmp_path):  # noqa: F811
    # xterm: in the foreground, ending with its command's status (xterm's own is 0)
    out = tmp_path / 'xterm.log'
    proc = run(programs, xdisplay, ['xterm', '-e', 'sh', '-c', 'echo from the node; exit 3'],
               out)
    assert proc.wait(20) == 3
    assert out.read_text() == 'from the node\n'
    # a signal that ends the command ends the program by it (roslaunch names it)
    proc = run(programs, xdisplay, ['xterm', '-e', 'sh', '-c', 'kill -ABRT $$'], tmp_path / 'a')
    assert proc.wait(20) == -6
    # gnome-terminal: returns as soon as its window is open, under its title
    out = tmp_path / 'gnome.log'
    proc = run(programs, xdisplay, ['gnome-terminal', '--title', 'the dog', '--', 'sh', '-c',
                                    'echo woof; sleep 3; echo done'], out)
    assert proc.wait(20) == 0
    assert 'the dog' in window_titles(xdisplay)
    deadline = time.monotonic() + 20
    while 'done' not in out.read_text() and time.monotonic() < deadline:
        time.sleep(0.2)
    assert out.read_text() == 'woof\ndone\n'
    # roslaunch ending a node in a window: its SIGINT reaches the command, as Ctrl-C would
    out = tmp_path / 'int.log'
    code = ('import signal, sys, time\n'
            'signal.signal(signal.SIGINT, lambda *_: (print("stopping", flush=True), '
            'sys.exit(0)))\nprint("up", flush=True)\ntime.sleep(30)\n')
    proc = run(programs, xdisplay, ['xterm', '-e', sys.executable, '-c', code], out)
    deadline = time.monotonic() + 20
    while 'up' not in out.read_text() and time.monotonic() < deadline:
        time.sleep(0.2)
    proc.send_signal(2)
    assert proc.wait(20) == 0
    assert out.read_text() == 'up\nstopping\n'


def test_no_display_is_one_line(programs):
    env = dict(os.environ, PATH='%s:/usr/bin:/bin' % programs)
    env.pop('DISPLAY', None)
    proc = subprocess.run(['gnome-terminal', '--', 'true'], env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True)
    assert proc.returncode == 1 and proc.stdout == ''
    assert proc.stderr == ('gnome-terminal: no display to open a window on (DISPLAY is not '
                           'set): run it in a desktop session, or under xvfb-run\n')

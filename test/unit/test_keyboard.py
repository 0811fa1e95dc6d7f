"""The keyboard of a node whose standard input is not a terminal (startup/exp2_keyboard.py).

In milliseconds: EXP2_KEYBOARD read, lines typed at their times (wall time, and ROS time
through a stand-in rospy), standard input with data read as it is, a library's read
given end-of-file. In real interpreters: a node started with stdin at /dev/null waits,
its other threads go on, SIGINT ends it, and one given lines gets them at their times.
"""
import io
import json
import os
import signal
import subprocess
import sys
import threading
import time
import types

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STARTUP = os.path.join(REPO, 'src', 'exp_assignment2', 'original_env', 'startup')
sys.path.insert(0, STARTUP)

import exp2_keyboard  # noqa: E402

PYTHON = '/usr/bin/python3'
WAITED = '[original-env] waited for keyboard input at '


def test_lines_to_type_for_this_process(tmp_path):
    lines = [{'at': 2, 'text': 'd'}, {'at': 0.5, 'text': 'm'}]
    assert exp2_keyboard.lines_to_type(json.dumps(lines), ['x.py']) == [(0.5, 'm'), (2.0, 'd')]
    per_process = json.dumps({'command_request.py': [{'at': 1, 'text': 'm'}],
                              'ball': [{'at': 3, 'text': 'b'}], '*': []})
    assert exp2_keyboard.lines_to_type(per_process, ['/p/scripts/command_request.py']) == [
        (1.0, 'm')]
    assert exp2_keyboard.lines_to_type(per_process, ['/p/x.py', '__name:=ball']) == [(3.0, 'b')]
    assert exp2_keyboard.lines_to_type(per_process, ['/p/other.py']) == []
    path = tmp_path / 'keys.json'
    path.write_text(json.dumps(lines))
    assert exp2_keyboard.lines_to_type(str(path), ['x.py'])[0] == (0.5, 'm')
    assert exp2_keyboard.lines_to_type('', ['x.py']) == []


@pytest.mark.parametrize('value,says', [
    ('[{"at": -1, "text": "m"}]', 'SECONDS >= 0'),
    ('[{"at": 1, "text": "two\\nlines"}]', 'one line'),
    ('[{"text": "m"}]', 'SECONDS'),
    ('{"at": 1}', 'expected a list'),
    ('[1, 2', 'not JSON'),
    ('/nonexistent/keys.json', 'cannot read /nonexistent/keys.json'),
])
def test_bad_lines_to_type_get_one_clear_line(value, says):
    with pytest.raises(exp2_keyboard.KeyboardError) as error:
        exp2_keyboard.lines_to_type(value, ['x.py'])
    assert says in str(error.value) and '\n' not in str(error.value)


def test_the_file_is_named_relative_to_its_package(tmp_path):
    (tmp_path / 'pkg' / 'scripts').mkdir(parents=True)
    (tmp_path / 'pkg' / 'package.xml').write_text('<package/>')
    assert exp2_keyboard.shown(str(tmp_path / 'pkg' / 'scripts' / 'ask.py')) == 'scripts/ask.py'


def test_standard_input_with_data_is_read_as_it_is():
    stdin = exp2_keyboard.KeyboardStdin(io.StringIO('m\nd\n'), [(0, 'never')])
    assert [stdin.readline(), stdin.read(), stdin.readline()] == ['m\n', 'd\n', '']
    assert list(exp2_keyboard.KeyboardStdin(io.StringIO('a\nb\n'), [])) == ['a\n', 'b\n']


def test_lines_are_typed_at_their_times_and_echoed(capsys):
    stdin = exp2_keyboard.KeyboardStdin(io.StringIO(''), [(0.0, 'm'), (0.05, 'd'), (0.1, 'xy')])
    start = time.monotonic()
    assert stdin.readline() == 'm\n'
    assert stdin.readline() == 'd\n'
    assert stdin.read(1) == 'x'
    assert time.monotonic() - start >= 0.1
    assert capsys.readouterr().out == 'm\nd\nxy\n'       # as a terminal echoes them


def test_a_librarys_read_gets_end_of_file():
    """Only the program's own code waits: a library that reads to the end is not stuck."""
    stdin = exp2_keyboard.KeyboardStdin(io.StringIO(''), [])
    library = {}
    exec(compile('def read_all(f):\n    return f.read()\n',
                 '/usr/lib/python3/dist-packages/somelib/io.py', 'exec'), library)
    assert library['read_all'](stdin) == ''


def test_ros_time_once_rospy_is_initialised(monkeypatch):
    clock = {'now': 10.0}
    cond = threading.Condition()
    rospy = types.SimpleNamespace(
        core=types.SimpleNamespace(is_initialized=lambda: True),
        rostime=types.SimpleNamespace(is_wallclock=lambda: False,
                                      get_rostime_cond=lambda: cond),
        get_time=lambda: clock['now'])
    monkeypatch.setitem(sys.modules, 'rospy', rospy)
    stdin = exp2_keyboard.KeyboardStdin(io.StringIO(''), [(12.0, 'm')])

    def tick():                     # /clock: 10.0 s, 10.5 s, ... of simulated time
        while clock['now'] < 13:
            time.sleep(0.01)
            with cond:
                clock['now'] += 0.5
                cond.notify_all()
    threading.Thread(target=tick, daemon=True).start()
    assert stdin.readline() == 'm\n'
    assert clock['now'] >= 12.0


def test_rospys_shutdown_ends_the_wait(monkeypatch):
    """rospy's SIGINT handler swallows Ctrl-C's KeyboardInterrupt: its shutdown ends the wait."""
    hooks, state = [], {'down': False}
    core = types.SimpleNamespace(is_initialized=lambda: True, add_preshutdown_hook=hooks.append,
                                 is_shutdown_requested=lambda: state['down'],
                                 is_shutdown=lambda: state['down'])
    monkeypatch.setitem(sys.modules, 'rospy', types.SimpleNamespace(core=core))
    stdin = exp2_keyboard.KeyboardStdin(io.StringIO(''), [])

    def shut_down():
        while not hooks:
            time.sleep(0.01)
        state['down'] = True
        hooks[0]('signal-2')
    threading.Thread(target=shut_down, daemon=True).start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        stdin.readline()
    assert time.monotonic() - start < 0.9      # the hook woke it, not the 1 s look


def start(script, tmp_path, env=None, stdin=subprocess.DEVNULL):
    (tmp_path / 'pkg' / 'scripts').mkdir(parents=True, exist_ok=True)
    (tmp_path / 'pkg' / 'package.xml').write_text('<package/>')
    path = tmp_path / 'pkg' / 'scripts' / 'command_request.py'
    path.write_text(script)
    environ = {k: v for k, v in os.environ.items() if not k.startswith('EXP2_')}
    environ.update(PYTHONPATH=STARTUP, PYTHONUNBUFFERED='1', **(env or {}))
    return subprocess.Popen([PYTHON, str(path)], cwd=str(tmp_path), env=environ, stdin=stdin,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True)


ASKS = '''import threading, time
def ticks():
    for _ in range(3):
        time.sleep(0.2)
        print("tick")
threading.Thread(target=ticks, daemon=True).start()
while True:
    command = input("Command: (m)ove ball, (d)isappear ball: ")
    print("got " + command)
'''


@pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')
def test_a_node_asking_with_stdin_at_dev_null_waits_until_interrupted(tmp_path):
    proc = start(ASKS, tmp_path)
    try:
        with pytest.raises(subprocess.TimeoutExpired):
            proc.wait(timeout=2)        # alive: as on a terminal nobody types into
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=10)
    finally:
        proc.kill()
    lines = out.splitlines()
    assert lines[0] == 'Command: (m)ove ball, (d)isappear ball: '
    assert lines[1] == WAITED + 'scripts/command_request.py:8'
    assert lines.count('tick') == 3                 # the other thread went on
    assert lines[-1] == 'KeyboardInterrupt' and proc.returncode == -signal.SIGINT  # as Python
    # the traceback ends on the student's line, as on a terminal
    assert 'exp2_' not in out and 'threading.py' not in out
    assert lines[lines.index('Traceback (most recent call last):') + 1].endswith(
        'command_request.py", line 8, in <module>')


@pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')
def test_a_node_given_lines_gets_them_at_their_times(tmp_path):
    keys = json.dumps({'command_request.py': [{'at': 0.3, 'text': 'm'},
                                              {'at': 0.6, 'text': 'd'}]})
    proc = start(ASKS.replace('threading.Thread', 'None and threading.Thread'), tmp_path,
                 {'EXP2_KEYBOARD': keys})
    try:
        with pytest.raises(subprocess.TimeoutExpired):
            proc.wait(timeout=2)
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=10)
    finally:
        proc.kill()
    prompt = 'Command: (m)ove ball, (d)isappear ball: '
    assert out.splitlines()[:6] == [prompt + 'm', 'got m', prompt + 'd', 'got d', prompt,
                                    WAITED + 'scripts/command_request.py:8']


@pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')
def test_piped_data_a_terminal_and_the_switch_are_left_alone(tmp_path):
    proc = start('import sys\nprint(sys.stdin.read().upper())\n', tmp_path,
                 stdin=subprocess.PIPE)
    assert proc.communicate('typed\n', timeout=30)[0] == 'TYPED\n\n'
    proc = start('input("x")\n', tmp_path, {'EXP2_KEYBOARD_WAIT': '0'})
    out, _ = proc.communicate(timeout=30)
    assert 'EOFError' in out and proc.returncode == 1

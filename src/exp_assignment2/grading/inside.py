"""The grader's driver inside a run's sandbox (standard library only: the
student's package may be called ``exp_assignment2`` too).

    /usr/bin/python3 inside.py PLAN.json

The plan (written by :mod:`exp_assignment2.grading.runner`) gives the
original-code shell, the package, the commands and the delay between them.
The driver builds the package (``original-env --package PKG true``), starts
a master, then each command through the original-code shell, a few seconds
apart, each in a process group of its own with its output in ``logs/``. It
reports what happens as JSON lines on its standard output (``built``,
``started``, ``exited``, ``ended``) and ends every command, gently then not,
when the grader writes ``stop`` on its standard input or closes it.
"""
import json
import os
import shlex
import signal
import subprocess
import sys
import threading
import time

MASTER_WAIT = 30.0      # s for the master to answer
GRACE = 8.0             # s between SIGINT and SIGTERM, and SIGTERM and SIGKILL


def emit(event, **fields):
    fields['event'] = event
    fields['wall'] = time.time()
    sys.stdout.write(json.dumps(fields) + '\n')
    sys.stdout.flush()


def original_env(plan, argv):
    return ['bash', plan['shell'], '--package', plan['package']] + argv


def start(plan, argv, log_name):
    log = open(os.path.join(plan['logs'], log_name), 'wb')
    try:
        return subprocess.Popen(original_env(plan, argv), stdout=log, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, start_new_session=True)
    finally:
        log.close()


def master_up(port=11311):
    import socket
    try:
        with socket.create_connection(('127.0.0.1', port), timeout=1.0):
            return True
    except OSError:
        return False


def end_all(procs):
    """SIGINT to every process group (as Ctrl-C), then SIGTERM, then SIGKILL."""
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGKILL):
        for proc in procs:
            if proc.poll() is None:
                try:
                    os.killpg(proc.pid, sig)
                except OSError:
                    pass
        deadline = time.monotonic() + GRACE
        while time.monotonic() < deadline and any(p.poll() is None for p in procs):
            time.sleep(0.1)


def main(argv):
    with open(argv[0]) as f:
        plan = json.load(f)
    os.makedirs(plan['logs'], exist_ok=True)
    stop = threading.Event()

    def wait_for_stop():
        for line in sys.stdin:
            if line.strip() == 'stop':
                break
        stop.set()
    threading.Thread(target=wait_for_stop, daemon=True).start()

    build = start(plan, ['true'], 'build.log')
    while build.poll() is None and not stop.is_set():
        time.sleep(0.2)
    if build.poll() is None:
        end_all([build])
    emit('built', rc=build.returncode)
    if build.returncode != 0:
        return 0

    procs = [start(plan, ['roscore', '-p', '11311'], 'roscore.log')]
    deadline = time.monotonic() + MASTER_WAIT
    while not master_up() and time.monotonic() < deadline and not stop.is_set():
        time.sleep(0.2)
    emit('master', up=master_up())
    commands, exited = [], set()
    for i, command in enumerate(plan['commands']):
        if stop.is_set():
            break
        if i:
            stop.wait(plan['delay'])
        try:
            words = shlex.split(command)
        except ValueError as exc:
            emit('exited', index=i, command=command, rc=None, error=str(exc))
            continue
        proc = start(plan, words, 'command-%d.log' % i)
        commands.append((i, command, proc))
        emit('started', index=i, command=command, pid=proc.pid)
    while not stop.is_set():
        for i, command, proc in commands:
            if i not in exited and proc.poll() is not None:
                exited.add(i)
                emit('exited', index=i, command=command, rc=proc.returncode)
        stop.wait(0.5)
    emit('stopping')
    end_all([proc for _, _, proc in reversed(commands)] + procs)
    for i, command, proc in commands:
        if i not in exited:
            emit('exited', index=i, command=command, rc=proc.returncode, at_end=True)
    emit('ended')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

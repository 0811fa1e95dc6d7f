"""The grader's driver inside a run's sandbox.

    /usr/bin/python3 inside.py PLAN.json

The plan (written by :mod:`exp_assignment2.grading.run.runner`) gives the
package, the commands and their start plan (:mod:`exp_assignment2.grading.plan.starts`:
when each starts, counted from the master, another's start or another's end,
and the folder it runs in). The driver makes the original-code environment
for the package once
(:func:`exp_assignment2.original_env.environment.environment`: the package
built in its overlay, its messages in ``logs/build.log``), starts a master,
then each command in that environment when the plan says, each in a
process group of its own with its output in ``logs/``. It reports what
happens as JSON lines on its standard output (``display``, ``built``, ``master``,
``started`` with ``at``: s after the master was up, and ``cwd``; ``exited``;
``never_started``: a command whose shell still waited at the end;
``stopping``, ``ended``) and ends every command, gently then not, when the
grader writes ``stop`` on its standard input or closes it.

The student's package may be called ``exp_assignment2`` too: this
package's library folder comes first on sys.path, so the library is ours.
"""
import json
import os
import shlex
import signal
import subprocess
import sys
import threading
import time

# run as a script: the library is three folders above this one's (the
# repository's src/, or an install space's dist-packages; exp_assignment2.layout)
SRC = os.path.realpath(os.path.join(os.path.dirname(os.path.realpath(__file__)),
                                    '..', '..', '..'))

MASTER_WAIT = 30.0      # s for the master to answer
GRACE = 3.0             # s between SIGINT and SIGTERM, and SIGTERM and SIGKILL: the run
                        # is over, and roslaunch alone waits 15 s for a node that ignores
                        # SIGINT (a real class: 16 s of a run's 250 at 8 s a step)


def emit(event, **fields):
    fields['event'] = event
    fields['wall'] = time.time()
    sys.stdout.write(json.dumps(fields) + '\n')
    sys.stdout.flush()


def build_error(exc):
    """The build's first error as data: {file, line, message} (file and line None if unknown)."""
    where, line = getattr(exc, 'where', None), None
    if where:
        head, _, tail = where.rpartition(':')
        if head and tail.isdigit():
            where, line = head, int(tail)
    return {'file': where, 'line': line, 'message': getattr(exc, 'message', None) or str(exc)}


def original_env(plan):
    """(the original-code environment for the plan's package, None), or
    (None, its first error as data) if it cannot be made (the reason's one
    line, and the build's progress, in logs/build.log, as the original-code
    shell prints them)."""
    sys.path.insert(0, SRC)
    from exp_assignment2.original_env.environment import NoWorkspace, environment
    from exp_assignment2.original_env.overlay.build import BuildFailed
    path = os.path.join(plan['logs'], 'build.log')
    with open(path, 'ab') as log:
        saved = os.dup(2)
        sys.stderr.flush()
        os.dup2(log.fileno(), 2)        # what the build prints, and what it runs
        try:
            env = environment(plan['package'], more=plan.get('more') or (),
                              bin_dir=plan.get('bin_dir'))
            sys.stderr.write('[original-env] enabled: %s\n' % env['EXP2_ORIGINAL_ENV'])
            return env, None
        except (NoWorkspace, BuildFailed) as exc:
            sys.stderr.write('[original-env] %s\n' % exc)
            return None, build_error(exc)
        except Exception as exc:        # a bug of ours: the grader's, said in the log
            sys.stderr.write('[original-env] the environment could not be made: %r\n' % exc)
            raise
        finally:
            sys.stderr.flush()
            os.dup2(saved, 2)
            os.close(saved)


def start_display(plan):
    """The run's own display (:mod:`exp_assignment2.grading.run.display`), its
    windows captured in ``display/`` beside the logs, ``DISPLAY`` set for
    everything started after; its processes, or None when it cannot be made
    (said in a ``display`` event: the grader's fault, and nothing is run)."""
    if SRC not in sys.path:
        sys.path.insert(0, SRC)
    from exp_assignment2.grading.run import display
    try:
        procs, name = display.start(os.path.join(os.path.dirname(plan['logs']), 'display'))
    except display.DisplayError as exc:
        emit('display', error=str(exc))
        return None
    os.environ['DISPLAY'] = name
    emit('display', display=name)
    return procs


def start(plan, env, argv, log_name, cwd=None):
    """``argv`` started in ``env`` (in folder ``cwd``), in a process group of
    its own, its output in logs/LOG_NAME (where an OSError, such as no such
    program, is said too)."""
    log = open(os.path.join(plan['logs'], log_name), 'wb')
    try:
        return subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=env, cwd=cwd,
                                stdin=subprocess.DEVNULL, start_new_session=True)
    except OSError as exc:
        log.write(('%s: %s\n' % (argv[0], exc.strerror or exc)).encode())
        raise
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
        for proc in procs:            # each waited on in turn, all within the grace
            try:
                proc.wait(timeout=max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                pass


def _plan_starts(plan):
    """The plan's starts (:mod:`exp_assignment2.grading.plan.starts`); a plan
    written before there were any: its commands ``delay`` apart."""
    from exp_assignment2.grading.plan import starts
    return plan.get('starts') or [dict(s, dir=None) for s in starts.typed(
        plan['commands'], plan['delay'])]


def follow_plan(plan, env, stop):
    """Each command started when the plan says (:func:`starts.follow`), in
    its folder, until ``stop``; ([(index, command, process)], {exited index})."""
    if SRC not in sys.path:
        sys.path.insert(0, SRC)
    from exp_assignment2.grading.plan import starts
    plan_starts = _plan_starts(plan)
    schedule = starts.Schedule(plan_starts, time.monotonic())
    commands, exited = [], set()

    def launch(i, at):
        entry = plan_starts[i]
        command, folder = entry['command'], entry.get('dir')
        where = dict(cwd=entry.get('cwd') or '', after=entry.get('after'),
                     since=entry.get('since'), at=round(at, 3))
        if not folder or not os.path.isdir(folder):
            folder = plan['package']
        try:
            words = shlex.split(command)
        except ValueError as exc:
            emit('exited', index=i, command=command, rc=None, error=str(exc), **where)
            return False
        if not words:
            emit('exited', index=i, command=command, rc=None, error='an empty command', **where)
            return False
        mine = env
        if entry.get('input') is not None:      # grading.yaml's lines to type into it
            mine = dict(env, EXP2_KEYBOARD=json.dumps(entry['input']))
        try:
            proc = start(plan, mine, words, 'command-%d.log' % i, cwd=folder)
        except OSError as exc:      # no such program: as the shell's exec said
            emit('exited', index=i, command=command, rc=127, error=str(exc), **where)
            return False
        commands.append((i, command, proc))
        emit('started', index=i, command=command, pid=proc.pid, **where)
        return True

    def poll_exits():
        ended = [i for i, _, proc in commands if i not in exited and proc.poll() is not None]
        exited.update(ended)
        return ended

    def told_exits(ended):
        for i, command, proc in commands:
            if i in ended:
                emit('exited', index=i, command=command, rc=proc.returncode)
    starts.follow(schedule, launch, poll_exits, told_exits, stop, time.monotonic)
    for i in schedule.never_started():     # a shell still waiting for what it ran
        entry = plan_starts[i]
        emit('never_started', index=i, command=entry['command'], cwd=entry.get('cwd') or '',
             after=entry.get('after'), since=entry.get('since'))
    return commands, exited


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

    shown = start_display(plan)     # before the environment: it reads DISPLAY
    if shown is None:
        return 0
    # in this thread: the overlay's lock times out with SIGALRM; a build past
    # the grader's limit ends with the sandbox
    env, error = original_env(plan)
    emit('built', rc=0 if env is not None else 1, error=error)
    if env is None:
        end_all(shown)
        return 0

    procs = [start(plan, env, ['roscore', '-p', '11311'], 'roscore.log')]
    deadline = time.monotonic() + MASTER_WAIT
    while not master_up() and time.monotonic() < deadline and not stop.wait(0.2):
        pass      # the master's port is all there is to watch
    emit('master', up=master_up())
    commands, exited = follow_plan(plan, env, stop)
    emit('stopping')
    end_all([proc for _, _, proc in reversed(commands)] + procs)
    end_all(shown)          # the display last: the student's windows close first
    for i, command, proc in commands:
        if i not in exited:
            emit('exited', index=i, command=command, rc=proc.returncode, at_end=True)
    emit('ended')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

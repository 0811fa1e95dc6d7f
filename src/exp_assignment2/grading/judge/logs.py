"""What the grader reads in a run's logs, in one place (no ROS).

* the Python errors in them: :mod:`.python_errors` (tracebacks, each once,
  and the SyntaxError of a script that could not start);
* :func:`deaths`: roslaunch's ``[NODE] process has died [pid, exit code, cmd]``
  lines, and its ``REQUIRED process [NODE] has died!`` (a ``required="true"``
  node: roslaunch then shuts its launch down), each with what the node said
  last: the lines of its output before it, its own log
  (``ros_home/log/RUN/NODE.log``, and ``NODE-stdout.log`` for
  ``output="log"``), and for an abort the Qt or C++ message before it
  (:func:`abort_message`); exit codes that are signals named
  (:func:`exit_name`); a node roslaunch restarts (``respawn="true"``) once,
  with how many times it died;
* :func:`cannot_launch`: roslaunch's ``ERROR: cannot launch node of type``,
  a node of a launch that could not be started (roslaunch runs the rest);
* :func:`started_nothing`: the line of a command's output that says the
  command started nothing (``RLException``, ``Resource not found``,
  ``rosrun``'s and ``rospack``'s errors);
* :class:`RequiredWatch`: the runner's look, while a run goes, for roslaunch's
  ``REQUIRED process [NODE] has died!`` (any other node's death ends nothing:
  roslaunch runs on, and so does the run).

Logs are read up to the size they had when the run was ended (``sizes``):
what a node says while it is being stopped is not its crash.
"""
import os
import re
import signal

READ_LIMIT = 4 * 1024 * 1024     # bytes of each log read
# roslaunch's colours, and the terminal title it sets (ESC ] 2 ; ... BEL)
ANSI = re.compile(r'\x1b\[[0-9;]*[A-Za-z]|\x1b\][^\x07\n]*(?:\x07|\x1b\\)')
TAIL = 15                        # lines of a dead node's output shown

DIED = re.compile(r'^\[(?P<node>[^\]]+)\] process has died \[pid \d+, exit code (?P<code>-?\d+), '
                  r'cmd (?P<cmd>.*?)\]\.?$', re.M)
# a required node's death: the banner, then the exit's description on the next line
REQUIRED = re.compile(r'REQUIRED process \[(?P<node>[^\]]+)\] has died!')
EXIT_DESCRIPTION = re.compile(r'^process has (?:died \[pid \d+, exit code (?P<code>-?\d+), '
                              r'cmd (?P<cmd>.*?)\]\.?|died without exit code \[pid \d+, '
                              r'cmd (?P<bare_cmd>.*?)\]\.?|finished cleanly)$')
RESTARTING = re.compile(r'^\[(?P<node>[^\]]+)\] restarting process$', re.M)
CANNOT_LAUNCH = re.compile(
    r'^ERROR: cannot launch node of type \[(?P<type>[^\]]+)\]: ?(?P<why>.*)$', re.M)
STARTED_NOTHING = re.compile(r'^(RLException: .*|Resource not found: .*|\[rosrun\] .*|'
                             r'\[rospack\] Error: .*|'
                             r'ERROR: .*is neither a launch file.*)$', re.M)
# what a process says before it aborts: Qt without a display, C++'s terminate,
# glibc's checks, a failed assertion, a segmentation fault
ABORT = re.compile(r'(qt\.qpa\.\S+: .*|.*Qt platform plugin.*|.*[Cc]annot (?:open|connect to) '
                   r'(?:display|X server).*|terminate called .*|\s*what\(\): .*|'
                   r'.*\*\*\* .+ \*\*\*.*|.*[Aa]ssertion .* failed.*|.*Segmentation fault.*|'
                   r'Fatal Python error: .*|(?:free|malloc|realloc|double free)\b.*\(\).*)$')
SIMULATOR = ('scripts/simulator.py', '/gzserver')
# roslaunch's own log: each node's whole command line, its __log:= file among its args
START_ARGS = re.compile(r'process\[[^\]]+\]: start w/ args \[\[(.*)\]\]')
QUOTED_LOG = re.compile(r"__log:=([^'\s,\]]+)")
LOG_ARG = re.compile(r'__log:=(\S+)')
COMMAND_LOG = re.compile(r'^logs/command-(\d+)\.log$')


def read_log(work, rel, sizes):
    """The log's text up to the size it had when the run was ended."""
    path = os.path.join(work, rel)
    limit = min(sizes.get(rel, READ_LIMIT), READ_LIMIT)
    try:
        with open(path, 'rb') as f:
            return ANSI.sub('', f.read(limit).decode(errors='replace'))
    except OSError:
        return ''


def run_logs(work, sizes):
    """[(rel path, text)] of the run's logs: the commands' then the nodes'."""
    names = sorted(sizes, key=lambda r: (not r.startswith('logs/'), r))
    return [(rel, read_log(work, rel, sizes)) for rel in names
            if not os.path.basename(rel).startswith(('master', 'rosout', 'roslaunch-'))]


def simulator_logs(work, sizes):
    """The rel paths of the simulator's own log files (its ``__log:=`` file and
    ``-stdout``/``-stderr``), as roslaunch's logs give its command line: what
    the simulator says is the grader's, never the student's."""
    found = set()
    for rel in sizes:
        if not os.path.basename(rel).startswith('roslaunch-'):
            continue
        for match in START_ARGS.finditer(read_log(work, rel, sizes)):
            if is_simulator(match.group(1)):
                log = QUOTED_LOG.search(match.group(1))
                if log:
                    found.update(r for r, _ in _own_logs('__log:=' + log.group(1), work, sizes))
    return found


def command_index(rel):
    """N of ``logs/command-N.log``, else None."""
    match = COMMAND_LOG.match(rel or '')
    return int(match.group(1)) if match else None


def last_lines(text, count=TAIL):
    lines = [l.rstrip() for l in text.splitlines() if l.strip()]
    return lines[-count:]


def last_line(text):
    lines = last_lines(text, 1)
    return lines[0].strip()[:300] if lines else ''


def exit_name(code):
    """``1``, ``-6 (SIGABRT)``: a negative exit code is the signal that ended it."""
    if code is None:
        return '?'
    if code < 0:
        try:
            return '%d (%s)' % (code, signal.Signals(-code).name)
        except ValueError:
            pass
    return str(code)


def abort_message(lines):
    """The Qt or C++ lines that say why a process aborted (the last of them,
    up to three, in their order), or ''."""
    found = [l.strip() for l in lines if ABORT.match(l)]
    kept = []
    for line in found[-3:]:
        if line not in kept:
            kept.append(line)
    return '\n'.join(kept)[:600]


def _own_logs(cmd, work, sizes):
    """[(rel, text)] of a node's own log files (its ``__log:=`` file, and the
    ``-stdout``/``-stderr`` files of ``output="log"``), read as the run left them."""
    match = LOG_ARG.search(cmd)
    if not match:
        return []
    path = match.group(1)
    base = path[:-len('.log')] if path.endswith('.log') else path
    found = []
    for candidate in (path, base + '-stdout.log', base + '-stderr.log'):
        rel = os.path.relpath(candidate, work) if os.path.isabs(candidate) else candidate
        if rel.startswith('..') and '/ros_home/' in candidate:
            # the sandbox sees the run's directory elsewhere (/tmp/exp2-grade-*/runs/L/work):
            # its ROS_HOME is the same place in both
            rel = 'ros_home/' + candidate.split('/ros_home/', 1)[1]
        if rel.startswith('..') or rel not in sizes:
            continue
        text = read_log(work, rel, sizes)
        if text.strip():
            found.append((rel, text))
    return found


def death(node, code, cmd, where, output_lines, work='', sizes=None):
    """One dead node: its exit (named), the lines of its output before its
    death, its own log's last lines, and the abort message in either."""
    own = _own_logs(cmd, work, sizes or {}) if work else []
    own_lines = [l for _, text in own for l in last_lines(text, TAIL)]
    return {'node': node, 'code': code, 'exit': exit_name(code), 'cmd': cmd[:300], 'log': where,
            'output': '\n'.join(output_lines[-TAIL:])[-4000:],
            'node_logs': [{'log': rel, 'tail': '\n'.join(last_lines(text))[-4000:]}
                          for rel, text in own],
            'abort': abort_message(output_lines[-40:] + own_lines)
            if code is not None and (code < 0 or code == 134) else ''}


def _died_at(lines, i):
    """(node, exit code, cmd, required?) of roslaunch's death said at line i, or None."""
    match = DIED.match(lines[i])
    if match:
        return match.group('node'), int(match.group('code')), match.group('cmd'), False
    match = REQUIRED.search(lines[i])
    if not match:
        return None
    said = EXIT_DESCRIPTION.match(lines[i + 1].strip()) if i + 1 < len(lines) else None
    if said is None or said.group('bare_cmd') is not None:     # no exit code known
        return match.group('node'), None, said.group('bare_cmd') if said else '', True
    code = int(said.group('code')) if said.group('code') is not None else 0
    return match.group('node'), code, said.group('cmd') or '', True


def deaths(logs, work='', sizes=None):
    """[death] for every node roslaunch said has died (``process has died``,
    ``REQUIRED process ... has died!``: ``required`` True, an exit code 0 too):
    a node roslaunch restarted (``respawn="true"``) once, with ``deaths``
    (how many times it died) and ``restarted`` (how many times roslaunch
    started it again), its first death's output kept."""
    found = []
    for rel, text in logs:
        lines = text.splitlines()
        restarts = {}
        for match in RESTARTING.finditer(text):
            restarts[match.group('node')] = restarts.get(match.group('node'), 0) + 1
        respawned = {}
        for i in range(len(lines)):
            said = _died_at(lines, i)
            if said is None:
                continue
            node, code, cmd, required = said
            if node in respawned:
                respawned[node]['deaths'] += 1
                continue
            before = [l for l in lines[max(0, i - 80):i] if l.strip()]
            dead = death(node, code, cmd, rel, before, work, sizes)
            dead['required'] = required
            if restarts.get(node):
                dead.update(deaths=1, restarted=restarts[node])
                respawned[node] = dead
            found.append(dead)
    return found


def is_simulator(death_or_cmd):
    cmd = death_or_cmd['cmd'] if isinstance(death_or_cmd, dict) else death_or_cmd
    return any(m in cmd for m in SIMULATOR)


def cannot_launch(logs):
    """[(rel, line)] of roslaunch's nodes that could not be started."""
    return [(rel, m.group(0).strip()[:400]) for rel, text in logs
            for m in CANNOT_LAUNCH.finditer(text)]


def started_nothing(text):
    """The first line of a command's output that says it started nothing, or None."""
    match = STARTED_NOTHING.search(text)
    return match.group(0).strip()[:300] if match else None


class RequiredWatch(object):
    """roslaunch's ``REQUIRED process [NODE] has died!`` in the commands' logs
    (``logs/command-N.log``), looked for as they grow: each byte read once."""

    CHUNK = 4 * 1024 * 1024      # bytes read from a log at one look

    def __init__(self, work):
        self.logs = os.path.join(work, 'logs')
        self._read, self._tails = {}, {}

    def death(self):
        """The name roslaunch gives the first required node that died, or None."""
        try:
            names = sorted(n for n in os.listdir(self.logs) if COMMAND_LOG.match('logs/' + n))
        except OSError:
            return None
        for name in names:
            try:
                with open(os.path.join(self.logs, name), 'rb') as f:
                    f.seek(self._read.get(name, 0))
                    chunk = f.read(self.CHUNK)
            except OSError:
                continue
            self._read[name] = self._read.get(name, 0) + len(chunk)
            text = self._tails.get(name, '') + chunk.decode(errors='replace')
            match = REQUIRED.search(ANSI.sub('', text))
            if match:
                return match.group('node')
            self._tails[name] = text[-400:]      # a line cut between two looks
        return None

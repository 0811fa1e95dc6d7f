"""A run's verdict, from what was seen outside the student's code (no ROS).

One of :data:`VERDICTS`, in this order of precedence:

* ``grader_error``: the machine's fault, never the student's: the sandbox
  did not start, the simulator died or never reported;
* ``not_built``: the submission does not unpack, or catkin fails (its first
  error);
* ``not_started``: a start command failed (which, and its error);
* ``crashed``: a node of the student's died before the end (which, and its
  traceback), or the run broke a limit of its sandbox (memory, disk);
* ``timed_out``: the run did not reach its simulated duration within its
  wall-clock limit, or the build took longer than its own;
* ``failed_checks`` / ``passed``: it ran; the profile's checks say.
"""
import os
import re

from exp_assignment2.grading import metrics
from exp_assignment2.grading.truth import read_record

VERDICTS = ('passed', 'failed_checks', 'crashed', 'timed_out', 'not_started', 'not_built',
            'grader_error')
DIED = re.compile(r'^\[(?P<node>[^\]]+)\] process has died \[pid \d+, exit code (?P<code>-?\d+), '
                  r'cmd (?P<cmd>.*?)\]\.?$', re.M)
NOT_LAUNCHED = re.compile(r'^(ERROR: cannot launch node of type \[[^\]]+\].*|'
                          r'RLException: .*|Resource not found: .*|'
                          r'\[rosrun\] .*|ERROR: .*(?:is neither a launch file|'
                          r'No such file or directory).*)$', re.M)
SIMULATOR = ('scripts/simulator.py', '/gzserver')
QUIET_ENDINGS = ('KeyboardInterrupt', 'ROSInterruptException', 'rospy.exceptions.ROSInterrupt',
                 'ROSTimeMovedBackwardsException')
READ_LIMIT = 4 * 1024 * 1024     # bytes of each log read
ANSI = re.compile(r'\x1b\[[0-9;]*[A-Za-z]')      # roslaunch's colours


def read_log(work, rel, sizes):
    """The log's text up to the size it had when the run was ended."""
    path = os.path.join(work, rel)
    limit = min(sizes.get(rel, READ_LIMIT), READ_LIMIT)
    try:
        with open(path, 'rb') as f:
            return ANSI.sub('', f.read(limit).decode(errors='replace'))
    except OSError:
        return ''


def _logs(work, sizes):
    """[(rel path, text)] of the run's logs: the commands' then the nodes'."""
    names = sorted(sizes, key=lambda r: (not r.startswith('logs/'), r))
    return [(rel, read_log(work, rel, sizes)) for rel in names
            if not os.path.basename(rel).startswith(('master', 'rosout', 'roslaunch-'))]


def python_errors(logs):
    """The tracebacks of the logs, each once (a node's stdout and its own log repeat them)."""
    seen, errors = set(), []
    for rel, text in logs:
        for error in metrics.tracebacks(text, rel):
            if any(error['summary'].startswith(q) or q in error['summary']
                   for q in QUIET_ENDINGS):
                continue
            key = error['excerpt'].split('Traceback', 1)[-1]
            if key in seen:
                continue
            seen.add(key)
            errors.append(error)
    return errors


def _first(pattern, logs):
    for rel, text in logs:
        match = pattern.search(text)
        if match:
            return rel, match
    return None, None


def judge(work, record, result, profile):
    """The fields the verdict adds to a run's result."""
    sizes = result.get('log_sizes') or {}
    logs = _logs(work, sizes)
    errors = python_errors(logs)
    events = result.get('events') or []
    out = {'errors': errors[:20], 'error_count': len(errors)}
    built = [e for e in events if e.get('event') == 'built']
    if not built:
        if result.get('ended_by') == 'build_limit':
            return dict(out, verdict='timed_out', reason='the build ran past its limit')
        text = read_log(work, 'logs/build.log', {})
        return dict(out, verdict='grader_error',
                    reason='the sandbox did not start (exit %s)%s' % (
                        result.get('sandbox_exit'),
                        ': ' + _last_line(text) if text else ''))
    if built[0].get('rc') != 0:
        text = read_log(work, 'logs/build.log', {})
        # paths as the report has them: relative to the run's directory
        return dict(out, verdict='not_built', reason=build_error(text).replace(
            os.path.join(work, 'src') + '/', '').replace(os.path.dirname(work) + '/', ''))
    died = []
    for rel, text in logs:
        for match in DIED.finditer(text):
            died.append({'node': match.group('node'), 'code': int(match.group('code')),
                         'cmd': match.group('cmd')[:300], 'log': rel})
    out['died'] = died
    simulator_died = [d for d in died if any(m in d['cmd'] for m in SIMULATOR)]
    if not any(e.get('event') in ('stopping', 'ended') for e in events) and \
            result.get('ended_by') == 'driver_exit':
        return dict(out, verdict='crashed', reason='the run\'s processes were killed from '
                    'inside its sandbox: the grader\'s driver there got a signal it was not '
                    'sent by the grader (exit %s)' % result.get('sandbox_exit'))
    if simulator_died and not result['truth']['states']:
        return dict(out, verdict='grader_error',
                    reason='the simulator died at start (%s, exit code %d)'
                    % (simulator_died[0]['node'], simulator_died[0]['code']))
    rel, match = _first(NOT_LAUNCHED, logs)
    failed = [e for e in events if e.get('event') == 'exited' and not e.get('at_end')
              and e.get('rc') not in (0, None) or e.get('error')]
    if match is not None or (failed and not result['truth']['states']):
        which = failed[0]['command'] if failed else _command_of(rel, result)
        line = match.group(0) if match is not None else _last_line(
            read_log(work, 'logs/command-%d.log' % failed[0]['index'], sizes))
        return dict(out, verdict='not_started', reason='%s: %s' % (which, line.strip()[:300]))
    if simulator_died:
        return dict(out, verdict='grader_error', reason='the simulator died (%s, exit code %d)'
                    % (simulator_died[0]['node'], simulator_died[0]['code']))
    if result.get('oom'):
        return dict(out, verdict='crashed', reason='the run used more than its %d MB of memory'
                    % profile['memory_limit_mb'])
    if result.get('ended_by') == 'disk_limit':
        return dict(out, verdict='crashed', reason='the run wrote more than its disk limit')
    student_died = [d for d in died if d['code'] != 0]
    if student_died:
        d = student_died[0]
        error = next((e for e in errors if e['source'] in (d['log'],) or
                      d['node'].rsplit('-', 1)[0] in e['source']), errors[0] if errors else None)
        return dict(out, verdict='crashed', reason='%s died (exit code %d)%s' % (
            d['node'], d['code'], ': ' + error['summary'] if error else ''))
    if result.get('ended_by') == 'no_simulator' or not result['truth']['states']:
        return dict(out, verdict='grader_error',
                    reason='the simulator never reported its ground truth')
    if result.get('ended_by') == 'wall_limit':
        return dict(out, verdict='timed_out', reason='%.0f of %.0f simulated s within the '
                    'wall-clock limit' % (result['truth']['sim_time'], profile['duration']))
    states, topics, _ = read_record(record)
    trace = metrics.Trace(states, topics, errors)
    checks = metrics.evaluate(trace, profile)
    passed = all(c['passed'] for c in checks)
    failed_names = [c['name'] for c in checks if not c['passed']]
    return dict(out, checks=checks, verdict='passed' if passed else 'failed_checks',
                reason='' if passed else 'failed: ' + ', '.join(failed_names))


def student_node_died(work):
    """Has a node other than the simulator died with an error (the commands' logs, now)?"""
    logs = os.path.join(work, 'logs')
    try:
        names = [n for n in os.listdir(logs) if n.startswith('command-')]
    except OSError:
        return False
    for name in names:
        text = read_log(work, os.path.join('logs', name), {})
        if any(int(m.group('code')) != 0 and not any(s in m.group('cmd') for s in SIMULATOR)
               for m in DIED.finditer(text)):
            return True
    return False


def _last_line(text):
    lines = [l for l in text.splitlines() if l.strip()]
    return lines[-1].strip()[:300] if lines else ''


def _command_of(rel, result):
    match = re.match(r'logs/command-(\d+)\.log', rel or '')
    if match and int(match.group(1)) < len(result.get('commands') or []):
        return result['commands'][int(match.group(1))]
    return rel or 'a command'


def build_error(text):
    """The first error of a build log (the original-code shell's one line)."""
    for line in text.splitlines():
        if line.startswith('[original-env]') and ('error' in line.lower() or
                                                  'fail' in line.lower() or ': ' in line) \
                and 'building ' not in line and 'installing' not in line:
            return line[len('[original-env]'):].strip()[:400]
    return _last_line(text) or 'the build failed'

"""A run's verdict, from what was seen outside the student's code (no ROS).

What was seen is gathered once (:func:`gather`: a :class:`Seen` from the
run's record, its logs through :mod:`exp_assignment2.grading.logs`, and its
ground truth); the verdict is the first rule of :data:`RULES` that holds,
as the CARLA leaderboard's ``FAILURE_MESSAGES`` table. The table's order is
the precedence (docs/grading.md, "Verdicts", lists it row by row):

1. ``grader_error``: the run's display could not be made (nothing of the student's ran);
2. ``grader_error``: the sandbox did not start (the driver never said the build's end);
3. ``grader_error``: the simulator died, with no memory limit broken and no
   grader's process killed from inside the sandbox (either would be the
   student's code's doing);
4. ``not_built``: the submission does not unpack, or catkin fails (its first error);
5. ``not_started``: a start command started nothing (``RLException``, a launch
   file that does not parse, ``rosrun`` of a missing node or package, no such
   program);
6. ``not_started``: the simulator never reported, and a node of a launch could
   not be started (its roslaunch's ``cannot launch node`` line);
7. ``crashed``: the grader's driver in the sandbox was killed from inside it;
8. ``crashed``: the run used more memory than its limit;
9. ``crashed``: the run wrote more than its disk limit;
10. ``crashed``: a node of the student's died before the end (which, its exit
   code named, its traceback or the Qt/C++ message of its abort);
11. ``grader_error``: the simulator never reported its ground truth;
12. ``timed_out``: the build ran past its limit;
13. ``timed_out``: the run did not reach its simulated duration within its
    wall-clock limit;
14. ``failed_checks``: some check of the profile failed;
15. ``passed``: every check that could be run passed (a check whose robot, head
    or ball could not be told is not run: :mod:`.roles`; the reason names it).

A node of a launch that cannot be started is not a verdict by itself
(roslaunch starts the rest, and so the student saw it run): it is kept in
``launch_errors``, attributed to the command whose output holds it, and
the verdict follows what the robot did.
"""
import collections
import os

from exp_assignment2.grading import logs as logs_
from exp_assignment2.grading import metrics
from exp_assignment2.grading import roles as roles_

VERDICTS = ('passed', 'failed_checks', 'crashed', 'timed_out', 'not_started', 'not_built',
            'grader_error')


class Seen(object):
    """The facts a verdict is decided on, gathered once (or made by hand in a test)."""

    def __init__(self, built=True, build_rc=0, build_error=None, build_log_line='',
                 ended_by='duration', sandbox_exit=0, driver_ended=True, oom=False,
                 states=0, sim_time=0.0, duration=200.0, memory_limit_mb=0, died=(),
                 errors=(), started_nothing=(), launch_errors=(), checks=None,
                 display_error=None):
        self.display_error = display_error       # the driver's, when it made no display
        self.built, self.build_rc, self.build_error = built, build_rc, build_error
        self.build_log_line = build_log_line
        self.ended_by, self.sandbox_exit, self.driver_ended = ended_by, sandbox_exit, driver_ended
        self.oom, self.states, self.sim_time, self.duration = oom, states, sim_time, duration
        self.memory_limit_mb = memory_limit_mb
        self.died, self.errors = list(died), list(errors)
        self.started_nothing, self.launch_errors = list(started_nothing), list(launch_errors)
        self._checks = checks      # a list, or a function judging (roles, checks) when asked
        self._roles = None

    def _judge(self):
        if callable(self._checks):
            self._roles, self._checks = self._checks()

    @property
    def checks(self):
        self._judge()
        return self._checks

    @property
    def roles(self):
        """The :class:`~.roles.Roles` the checks judged (None before any ground truth)."""
        self._judge()
        return self._roles

    @property
    def ran(self):
        """The package was built and its commands were started."""
        return self.built and self.build_rc == 0

    @property
    def killed_from_inside(self):
        """The driver ended without ending its commands, and the grader did not end it."""
        return self.ran and not self.driver_ended and self.ended_by == 'driver_exit'

    @property
    def simulator_deaths(self):
        return [d for d in self.died if logs_.is_simulator(d)]

    @property
    def student_deaths(self):
        return [d for d in self.died if d['code'] != 0 and not logs_.is_simulator(d)]


Rule = collections.namedtuple('Rule', 'verdict name holds reason')


def _simulator_died_reason(s):
    d = s.simulator_deaths[0]
    return 'the simulator died%s (%s, exit code %s)' % (' at start' if not s.states else '',
                                                         d['node'], logs_.exit_name(d['code']))


def _build_reason(s):
    error = s.build_error or {}
    where = error.get('file') or ''
    if where and error.get('line'):
        where += ':%s' % error['line']
    message = error.get('message') or s.build_log_line or 'the build failed'
    return '%s%s' % (where + ': ' if where else '', message)


def _death_reason(s):
    d = s.student_deaths[0]
    error = next((e for e in s.errors if e['source'] == d['log'] or
                  d['node'].rsplit('-', 1)[0] in e['source']), s.errors[0] if s.errors else None)
    why = error['summary'] if error else (d.get('abort') or '').split('\n')[0]
    return '%s died (exit code %s)%s' % (d['node'], logs_.exit_name(d['code']),
                                         ': ' + why if why else '')


def _failed_names(s):
    return [c['name'] for c in s.checks or () if c['passed'] is False]


def _checks_reason(s):
    """Which checks failed, and which were not run (their role could not be told)."""
    parts = []
    if _failed_names(s):
        parts.append('failed: ' + ', '.join(_failed_names(s)))
    unjudged = [c['name'] for c in s.checks or () if c['passed'] is None]
    if unjudged:
        parts.append('not judged: ' + ', '.join(unjudged))
    return '; '.join(parts)


RULES = (
    Rule('grader_error', 'no display', lambda s: bool(s.display_error),
         lambda s: 'the run\'s display could not be made: %s' % s.display_error),
    Rule('grader_error', 'sandbox did not start',
         lambda s: not s.built and s.ended_by != 'build_limit',
         lambda s: 'the sandbox did not start (exit %s)%s' % (
             s.sandbox_exit, ': ' + s.build_log_line if s.build_log_line else '')),
    Rule('grader_error', 'simulator died',
         lambda s: s.ran and bool(s.simulator_deaths) and not s.oom and not s.killed_from_inside,
         _simulator_died_reason),
    Rule('not_built', 'build failed', lambda s: s.built and s.build_rc != 0, _build_reason),
    Rule('not_started', 'a command started nothing',
         lambda s: s.ran and bool(s.started_nothing),
         lambda s: '%s: %s' % s.started_nothing[0]),
    Rule('not_started', 'nothing ran, a node could not launch',
         lambda s: s.ran and not s.states and bool(s.launch_errors),
         lambda s: '%s: %s' % (s.launch_errors[0]['command'], s.launch_errors[0]['line'])),
    Rule('crashed', 'the grader\'s processes killed from inside',
         lambda s: s.killed_from_inside,
         lambda s: 'the run\'s processes were killed from inside its sandbox: the grader\'s '
                   'driver there got a signal it was not sent by the grader (exit %s)'
                   % s.sandbox_exit),
    Rule('crashed', 'memory limit', lambda s: s.ran and s.oom,
         lambda s: 'the run used more than its %d MB of memory' % s.memory_limit_mb),
    Rule('crashed', 'disk limit', lambda s: s.ran and s.ended_by == 'disk_limit',
         lambda s: 'the run wrote more than its disk limit'),
    Rule('crashed', 'a node died', lambda s: s.ran and bool(s.student_deaths), _death_reason),
    Rule('grader_error', 'no ground truth',
         lambda s: s.ran and (not s.states or s.ended_by == 'no_simulator'),
         lambda s: 'the simulator never reported its ground truth'),
    Rule('timed_out', 'build limit', lambda s: not s.built and s.ended_by == 'build_limit',
         lambda s: 'the build ran past its limit'),
    Rule('timed_out', 'wall-clock limit', lambda s: s.ran and s.ended_by == 'wall_limit',
         lambda s: '%.0f of %.0f simulated s within the wall-clock limit' % (s.sim_time,
                                                                            s.duration)),
    Rule('failed_checks', 'a check failed', lambda s: bool(_failed_names(s)), _checks_reason),
    Rule('passed', 'every check that could be run passed', lambda s: True, _checks_reason),
)


def decide(seen, rules=RULES):
    """(verdict, reason) of the first rule that holds."""
    for rule in rules:
        if rule.holds(seen):
            return rule.verdict, rule.reason(seen)
    raise AssertionError('no rule holds')      # the last one always does


def _command_names(result):
    """{index: command} as the driver said it started them (else as planned)."""
    names = dict(enumerate(result.get('commands') or []))
    for event in result.get('events') or []:
        if event.get('event') in ('started', 'exited') and 'index' in event:
            names[event['index']] = event.get('command', names.get(event['index']))
    return names


def _command_of(rel, names):
    index = logs_.command_index(rel)
    if index is None:
        return rel or 'a command'
    return names.get(index, 'command %d' % index)


def gather(work, record_dir, result, profile):
    """The :class:`Seen` of a finished run."""
    sizes = result.get('log_sizes') or {}
    run_logs = logs_.run_logs(work, sizes)
    simulators = logs_.simulator_logs(work, sizes)    # the grader's: not the student's errors
    events = result.get('events') or []
    built = next((e for e in events if e.get('event') == 'built'), None)
    names = _command_names(result)
    states = (result.get('truth') or {}).get('states') or 0
    build_log = logs_.read_log(work, 'logs/build.log', {})
    error = dict(built.get('error') or {}) if built else None
    if error and error.get('file'):        # as the report has paths: the package's own
        package = os.path.join(work, 'src') + '/'
        error['file'] = error['file'].replace(package, '').replace(
            os.path.dirname(work) + '/', '')
    seen = Seen(built=built is not None, build_rc=built.get('rc') if built else None,
                build_error=error, build_log_line=logs_.last_line(build_log),
                ended_by=result.get('ended_by'), sandbox_exit=result.get('sandbox_exit'),
                driver_ended=any(e.get('event') in ('stopping', 'ended') for e in events),
                oom=bool(result.get('oom')), states=states,
                sim_time=(result.get('truth') or {}).get('sim_time') or 0.0,
                duration=float(result.get('duration') or profile['duration']),
                memory_limit_mb=profile['memory_limit_mb'],
                errors=logs_.python_errors(
                    [(rel, text) for rel, text in run_logs if rel not in simulators]),
                display_error=next((e['error'] for e in events if e.get('event') == 'display'
                                    and e.get('error')), None))
    if not seen.ran:
        return seen
    seen.died = logs_.deaths(run_logs, work, sizes)
    seen.launch_errors = [{'command': _command_of(rel, names), 'line': line, 'log': rel}
                          for rel, line in logs_.cannot_launch(run_logs)]
    texts = dict(run_logs)
    nothing = []       # (inferred?, index, command, line): said first, then by order
    for event in events:
        if event.get('event') != 'exited' or event.get('at_end'):
            continue
        index, command = event.get('index', -1), event.get('command')
        rel = 'logs/command-%d.log' % index
        text = texts.get(rel) or logs_.read_log(work, rel, sizes)
        line = logs_.started_nothing(text)
        if event.get('error'):                 # the driver could not start it
            nothing.append((0, index, command, event['error'][:300]))
        elif line:
            nothing.append((0, index, command, line))
        elif event.get('rc') not in (0, None) and not states:
            nothing.append((1, index, command, logs_.last_line(text) or 'exited with code %s'
                            % logs_.exit_name(event['rc'])))
        elif event.get('rc') not in (0, None) and not (command or '').startswith('roslaunch '):
            # a rosrun'd node (roslaunch says its nodes' deaths itself)
            seen.died.append(logs_.death(command, event['rc'], command, rel,
                                         logs_.last_lines(text, 80)))
    for rel, text in run_logs:                 # said by a command not seen to exit before the end
        index = logs_.command_index(rel)
        line = logs_.started_nothing(text)
        if index is not None and line and not any(n[1] == index for n in nothing):
            nothing.append((0, index, names.get(index, rel), line))
    seen.started_nothing = [(command, line) for _, _, command, line in sorted(nothing)]

    def judged():
        trace = metrics.Trace.from_record(record_dir, seen.errors)
        found = roles_.find(trace, profile)
        return found, metrics.evaluate(trace, profile, found)
    seen._checks = judged if states else None
    return seen


def judge(work, record_dir, result, profile):
    """The fields the verdict adds to a run's record."""
    seen = gather(work, record_dir, result, profile)
    verdict, reason = decide(seen)
    out = {'verdict': verdict, 'reason': reason, 'errors': seen.errors[:20],
           'error_count': len(seen.errors)}
    if seen.ran:
        out.update(died=seen.died, launch_errors=seen.launch_errors)
    if verdict in ('passed', 'failed_checks'):
        out['checks'] = seen.checks
    elif verdict in ('crashed', 'timed_out') and seen.checks is not None:
        # judged from the ground truth recorded until the end: the points earned so far
        out['checks'] = seen.checks
        out['checks_until'] = verdict
    if seen.roles is not None:        # which robot, head, camera and ball were judged, and why
        out['roles'] = seen.roles.to_dict()
    return out

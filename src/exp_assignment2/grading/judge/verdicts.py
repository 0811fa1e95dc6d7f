"""A run's verdict, from what was seen outside the student's code (no ROS).

What was seen is gathered once (:func:`~exp_assignment2.grading.judge.seen.gather`:
a :class:`~exp_assignment2.grading.judge.seen.Seen` from the run's record, its logs
through :mod:`exp_assignment2.grading.judge.logs`, and its ground truth); the
verdict is the first rule of :data:`RULES` that holds, as the CARLA
leaderboard's ``FAILURE_MESSAGES`` table. The table's order is the precedence
(docs/grading.md, "Verdicts", lists it row by row). Rows 1-5 are facts a
run's record says itself (:data:`~exp_assignment2.grading.judge.seen.TOLD`,
written by the runner or the teacher's side; nothing else is read for them),
the grader's own faults first, as in rows 6-8:

1. ``grader_error``: the run was refused on the teacher's side (``grading.yaml``
   is wrong about it, or the grader could not read it): nothing ran;
2. ``grader_error``: Dask gave up on it, its workers lost too often;
3. ``grader_error``: the grader itself failed with it (sending it to a
   worker, running it, judging it, receiving it): what was seen until then
   is not the student's doing;
4. ``not_built``: the submission cannot be taken (it does not unpack, it
   holds no package, it is not a folder or an archive);
5. ``grader_error``: its sandbox could not be made;
6. ``grader_error``: the run's display could not be made (nothing of the student's ran);
7. ``grader_error``: the sandbox did not start (the driver never said the build's end);
8. ``grader_error``: the simulator died, with no memory limit broken and no
   grader's process killed from inside the sandbox (either would be the
   student's code's doing);
9. ``not_built``: catkin fails (its first error);
10. ``not_started``: a start command started nothing (``RLException``, a launch
    file that does not parse, ``rosrun`` of a missing node or package, no such
    program);
11. ``not_started``: the simulator never reported, and a node of a launch could
    not be started (its roslaunch's ``cannot launch node`` line);
12. ``crashed``: the grader's driver in the sandbox was killed from inside it,
13. ``crashed``: the run used more memory than its limit,
14. ``crashed``: the run wrote more than its disk limit,
15. ``crashed``: a ``required="true"`` node died, and roslaunch shut its
    launch down (``REQUIRED process [NODE] has died!``),
16. ``crashed``: every command had ended (the system was gone) before the
    duration, the ground truth having come,
    each of 12-16 only when some check was not met on the ground truth until
    then (a system that did its work and then ended is judged by its checks);
17. ``grader_error``: the simulator never reported its ground truth;
18. ``grader_error``: the run fell behind real time beside other runs and was
    ended to be run again alone, and was not (the grading stopped first);
19. ``timed_out``: the build ran past its limit;
20. ``timed_out``: the run did not reach its simulated duration within its
    wall-clock limit;
21. ``failed_checks``: some check of the profile failed (the nodes that died
    named after them);
22. ``passed``: every check that could be run passed (a check whose robot, head
    or ball could not be told is not run: :mod:`~exp_assignment2.grading.judge.roles`; the reason
    names it, and the nodes that died).

roslaunch's rules, as on the student's desktop: a node of a launch that
cannot be started, or that dies, is not a verdict by itself (roslaunch
starts the rest and runs on; it restarts a ``respawn="true"`` node): the
death is kept in ``died``, its traceback counts as a Python error, and the
verdict follows the checks. A node that cannot be started is kept in
``launch_errors``, attributed to the command whose output holds it.
"""
import collections
import os

from exp_assignment2.grading.judge import logs as logs_
from exp_assignment2.grading.judge.seen import Seen, gather, told

__all__ = ['RULES', 'Seen', 'VERDICTS', 'decide', 'gather', 'judge', 'judge_told',
           'why_it_died']
VERDICTS = ('passed', 'failed_checks', 'crashed', 'timed_out', 'not_started', 'not_built',
            'grader_error')


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


def why_it_died(errors, d):
    """What a dead node said last: its traceback (in its own log, in the output
    before its death, in its command's log), else its abort's message."""
    own = {l['log'] for l in d.get('node_logs') or ()}
    for fits in (lambda e: e['source'] in own or
                 os.path.basename(e['source']).startswith(d['node'] + '.'),
                 lambda e: e['summary'] in (d.get('output') or ''),
                 lambda e: e['source'] == d['log']):
        error = next((e for e in errors if fits(e)), None)
        if error:
            return error['summary']
    return (d.get('abort') or '').split('\n')[0]


def _death(s, d):
    """'NODE died (exit code N): why', with how often when roslaunch restarted it."""
    times = ' %d times' % d['deaths'] if d.get('deaths', 1) > 1 else ''
    again = ', restarted by roslaunch (respawn)' if d.get('restarted') else ''
    why = why_it_died(s.errors, d)
    return '%s died%s (exit code %s)%s%s' % (d['node'], times, logs_.exit_name(d['code']),
                                             again, ': ' + why if why else '')


def _deaths_said(s, shown=2):
    """The student's nodes that died, for a verdict's reason ('' when none)."""
    deaths = s.student_deaths
    said = '; '.join(_death(s, d) for d in deaths[:shown])
    more = len(deaths) - shown
    return said + ('; and %d other node%s' % (more, 's' if more > 1 else '') if more > 0 else '')


def _at(s):
    return 'at %.0f of %.0f simulated s' % (s.ended_at, s.duration)


def _required_reason(s):
    d = next((d for d in s.student_deaths if d.get('required')), None)
    said = _death(s, d) if d else 'a required node died'
    return '%s; it was required="true": roslaunch shut its launch down %s' % (said, _at(s))


def _all_ended_reason(s):
    deaths = _deaths_said(s)
    return 'every command had ended %s%s' % (_at(s), ' (%s)' % deaths if deaths else '')


def _checks_reason(s):
    """Which checks failed, which were not run (their role could not be told),
    and the student's nodes that died meanwhile (roslaunch ran on)."""
    parts = []
    if s.failed:
        parts.append('failed: ' + ', '.join(s.failed))
    unjudged = [c['name'] for c in s.checks or () if c['passed'] is None]
    if unjudged:
        parts.append('not judged: ' + ', '.join(unjudged))
    if _deaths_said(s):
        parts.append(_deaths_said(s))
    return '; '.join(parts)


def _fault_reason(s):
    return 'the grader %s (a fault of the grader\'s, not the student\'s): %s' % (
        s.grader_fault['what'], s.grader_fault['error'])


RULES = (
    Rule('grader_error', 'refused', lambda s: bool(s.refused), lambda s: s.refused),
    Rule('grader_error', 'lost', lambda s: bool(s.lost),
         lambda s: 'the grader lost this run: %s' % s.lost),
    Rule('grader_error', "a fault of the grader's", lambda s: bool(s.grader_fault),
         _fault_reason),
    Rule('not_built', 'cannot be taken', lambda s: bool(s.rejected), lambda s: s.rejected),
    Rule('grader_error', 'no sandbox', lambda s: bool(s.sandbox_error),
         lambda s: s.sandbox_error),
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
         lambda s: s.ended_early(lambda s: s.killed_from_inside),
         lambda s: 'the run\'s processes were killed from inside its sandbox: the grader\'s '
                   'driver there got a signal it was not sent by the grader (exit %s)'
                   % s.sandbox_exit),
    Rule('crashed', 'memory limit', lambda s: s.ended_early(lambda s: s.oom),
         lambda s: 'the run used more than its %d MB of memory' % s.memory_limit_mb),
    Rule('crashed', 'disk limit', lambda s: s.ended_early(lambda s: s.ended_by == 'disk_limit'),
         lambda s: 'the run wrote more than its disk limit'),
    Rule('crashed', 'a required node died',
         lambda s: s.ended_early(lambda s: s.ended_by == 'required_node_died'),
         _required_reason),
    Rule('crashed', 'every command ended',
         lambda s: s.ended_early(lambda s: s.ended_by == 'all_exited' and bool(s.states)),
         _all_ended_reason),
    Rule('grader_error', 'no ground truth',
         lambda s: s.ran and (not s.states or s.ended_by == 'no_simulator'),
         lambda s: 'the simulator never reported its ground truth'),
    Rule('grader_error', 'starved beside other runs', lambda s: s.ran and s.ended_by == 'starved',
         lambda s: 'this machine could not keep it at real time beside other runs: ended %s '
                   'to be run again alone, and it was not (the grading was stopped)' % _at(s)),
    Rule('timed_out', 'build limit', lambda s: not s.built and s.ended_by == 'build_limit',
         lambda s: 'the build ran past its limit'),
    Rule('timed_out', 'wall-clock limit', lambda s: s.ran and s.ended_by == 'wall_limit',
         lambda s: '%.0f of %.0f simulated s within the wall-clock limit' % (s.sim_time,
                                                                            s.duration)),
    Rule('failed_checks', 'a check failed', lambda s: bool(s.failed), _checks_reason),
    Rule('passed', 'every check that could be run passed', lambda s: True, _checks_reason),
)


def decide(seen, rules=RULES):
    """(verdict, reason) of the first rule that holds."""
    for rule in rules:
        if rule.holds(seen):
            return rule.verdict, rule.reason(seen)
    raise AssertionError('no rule holds')      # the last one always does


def judge_told(result):
    """The verdict and reason of a run whose record says itself how it ended
    (:func:`~exp_assignment2.grading.judge.seen.told`): nothing else is read."""
    seen = told(result)
    if seen is None:
        raise ValueError('judge_told: the record says no end of its own (seen.TOLD)')
    verdict, reason = decide(seen)
    return {'verdict': verdict, 'reason': reason}


def judge(work, record_dir, result, profile):
    """The fields the verdict adds to a run's record."""
    if told(result) is not None:
        return judge_told(result)
    seen = gather(work, record_dir, result, profile)
    verdict, reason = decide(seen)
    out = {'verdict': verdict, 'reason': reason, 'errors': seen.errors[:20],
           'error_count': len(seen.errors)}
    if seen.ran:
        out.update(died=seen.died, launch_errors=seen.launch_errors)
        if seen.keyboard:     # it waited for a person: the page says where
            out['keyboard'] = seen.keyboard
    if verdict in ('passed', 'failed_checks'):
        out['checks'] = seen.checks
        if seen.release_evidence is not None:
            out['release_evidence'] = seen.release_evidence
    elif verdict in ('crashed', 'timed_out') and seen.checks is not None:
        # judged from the ground truth recorded until the end: the points earned so far
        out['checks'] = seen.checks
        out['checks_until'] = verdict
    if seen.roles is not None:        # which robot, head, camera and ball were judged, and why
        out['roles'] = seen.roles.to_dict()
    return out

"""The facts a run's verdict is decided on (no ROS): :class:`Seen`, gathered
once from the run's record, its logs (through
:mod:`exp_assignment2.grading.judge.logs`) and its ground truth by :func:`gather`,
or made by hand in a test; :mod:`exp_assignment2.grading.judge.verdicts` decides on them.
"""
import os
import re

from exp_assignment2.grading.judge import logs as logs_
from exp_assignment2.grading.judge import metrics
from exp_assignment2.grading.judge.python_errors import name_missing, python_errors
from exp_assignment2.grading.judge import roles as roles_
from exp_assignment2.grading.judge import steering
from exp_assignment2.grading.plan import profile_keys


# the facts a record says itself of an end before or outside its run: the
# teacher's side refused it (refused), its submission cannot be taken
# (rejected), Dask gave up on it (lost), the grader failed with it
# (grader_fault: {'what', 'error'}), or its sandbox could not be made
# (sandbox_error); nothing of the run is read then
TOLD = ('refused', 'lost', 'grader_fault', 'rejected', 'sandbox_error')


class Seen(object):
    """The facts a verdict is decided on, gathered once (or made by hand in a test)."""

    def __init__(self, built=True, build_rc=0, build_error=None, build_log_line='',
                 ended_by='duration', sandbox_exit=0, driver_ended=True, oom=False,
                 states=0, sim_time=0.0, duration=200.0, memory_limit_mb=0, died=(),
                 errors=(), started_nothing=(), launch_errors=(), checks=None,
                 display_error=None, ended_at=None, refused=None, lost=None,
                 grader_fault=None, rejected=None, sandbox_error=None):
        self.refused, self.lost, self.grader_fault = refused, lost, grader_fault
        self.rejected, self.sandbox_error = rejected, sandbox_error
        self.display_error = display_error       # the driver's, when it made no display
        self.ended_at = sim_time if ended_at is None else ended_at     # simulated s at the end
        self.built, self.build_rc, self.build_error = built, build_rc, build_error
        self.build_log_line = build_log_line
        self.ended_by, self.sandbox_exit, self.driver_ended = ended_by, sandbox_exit, driver_ended
        self.oom, self.states, self.sim_time, self.duration = oom, states, sim_time, duration
        self.memory_limit_mb = memory_limit_mb
        self.died, self.errors = list(died), list(errors)
        self.started_nothing, self.launch_errors = list(started_nothing), list(launch_errors)
        self._checks = checks      # a list, or a function judging (roles, checks) when asked
        self._roles = None
        self.keyboard = []         # [{'where': FILE:LINE, 'command'}]: reads nobody answered
        self.release_evidence = None    # judge.steering's, once the checks are judged

    def _judge(self):
        if callable(self._checks):
            self._roles, self._checks = self._checks()

    @property
    def checks(self):
        self._judge()
        return self._checks

    @property
    def roles(self):
        """The :class:`~exp_assignment2.grading.judge.roles.Roles` the checks judged (None before
        any ground truth)."""
        self._judge()
        return self._roles

    @property
    def told(self):
        """The run's record says how it ended before or outside its run (:data:`TOLD`)."""
        return any(getattr(self, key) for key in TOLD)

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
        """The student's nodes that died: with an error, or required (roslaunch then
        shut its launch down however it ended)."""
        return [d for d in self.died if (d['code'] != 0 or d.get('required')) and
                not logs_.is_simulator(d)]

    @property
    def failed(self):
        """The names of the checks that failed."""
        return [c['name'] for c in self.checks or () if c['passed'] is False]

    @property
    def checks_met(self):
        """Every check that could be judged passed (never before any ground truth)."""
        return self.checks is not None and not self.failed

    def ended_early(self, how):
        """The system ended (``how`` holds) before its checks were met."""
        return self.ran and how(self) and not self.checks_met


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


KEYBOARD_WAIT = re.compile(r'^\[original-env\] waited for keyboard input at (\S+)', re.M)


def keyboard_waits(run_logs, names):
    """[{'where', 'command'}] of the original-code environment's line for a
    node that read the keyboard while nobody typed (it waited, as on a
    terminal nobody types into), each place once."""
    found, seen = [], set()
    for rel, text in run_logs:
        for match in KEYBOARD_WAIT.finditer(text):
            if match.group(1) not in seen:
                seen.add(match.group(1))
                found.append({'where': match.group(1), 'command': _command_of(rel, names)})
    return found


def in_run(path, work):
    """``path`` (the build's, where the run was: a worker's scratch directory,
    or the report's copy judged again) as the report names it: from the
    submission's root, else from the run's directory."""
    marker = '/runs/%s/work/' % os.path.basename(os.path.dirname(work))
    at = path.find(marker)
    if path.startswith(work.rstrip('/') + '/'):
        rest = path[len(work.rstrip('/')) + 1:]
    elif at >= 0:
        rest = path[at + len(marker):]
    else:
        return path
    return rest[len('src/'):] if rest.startswith('src/') else 'work/' + rest


def told(result):
    """The :class:`Seen` of a run whose record says itself how it ended before
    or outside its run (:data:`TOLD`), read from nothing else; else None."""
    facts = {key: result.get(key) for key in TOLD if result.get(key)}
    if not facts:
        return None
    return Seen(built=False, build_rc=None, ended_by=result.get('ended_by'),
                sandbox_exit=result.get('sandbox_exit'), **facts)


def gather(work, record_dir, result, profile):
    """The :class:`Seen` of a finished run (:func:`told`'s, when its record says it)."""
    said = told(result)
    if said is not None:
        return said
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
        error['file'] = in_run(error['file'], work)
    seen = Seen(built=built is not None, build_rc=built.get('rc') if built else None,
                build_error=error, build_log_line=logs_.last_line(build_log),
                ended_by=result.get('ended_by'), sandbox_exit=result.get('sandbox_exit'),
                driver_ended=any(e.get('event') in ('stopping', 'ended') for e in events),
                oom=bool(result.get('oom')), states=states,
                sim_time=(result.get('truth') or {}).get('sim_time') or 0.0,
                duration=float(result.get('duration') or profile['duration']),
                memory_limit_mb=profile['memory_limit_mb'],
                errors=name_missing(python_errors(
                    [(rel, text) for rel, text in run_logs if rel not in simulators]),
                    {p.get('name') for p in result.get('packages') or []}),
                display_error=next((e['error'] for e in events if e.get('event') == 'display'
                                    and e.get('error')), None),
                ended_at=result.get('ended_at'))
    if not seen.ran:
        return seen
    seen.died = logs_.deaths(run_logs, work, sizes)
    seen.keyboard = keyboard_waits(run_logs, names)
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
        # what the run shows of its release, read before another release is tried
        seen.release_evidence = steering.evidence(
            trace, found, profile_keys.with_shared({}, profile), seen.errors)
        return found, metrics.evaluate(trace, profile, found)
    seen._checks = judged if states else None
    return seen

"""One run of one submission, from its files to its record (no ROS).

A run's directory (``RUNS/<name>[-rN]/``) holds ``work/`` (the only place
the sandbox may write: the unpacked submission, its build, its logs, its
``ROS_HOME``) and ``record/`` (the grader's: the ground truth, the driver's
events, the frames, ``run.json``). The sandbox never sees ``record/``: the
simulator's socket is in ``sockets/``, shown to it read-only.
"""
import json
import os
import shutil
import subprocess
import threading
import time

from exp_assignment2.grading.plan import build_deps
from exp_assignment2.grading.run import cpu
from exp_assignment2.grading.judge import logs
from exp_assignment2.grading import record
from exp_assignment2.grading.run import ending as run_end
from exp_assignment2.grading.plan import starts
from exp_assignment2.grading.judge import verdicts
from exp_assignment2.grading.plan import packages as packages_
from exp_assignment2.grading.paths import INSIDE, REPO
from exp_assignment2.grading.run.files import directory_size, log_sizes, waits_on_wall_clock
from exp_assignment2.grading.run.sandbox import Sandbox, SandboxError
from exp_assignment2.grading.plan.submissions import Submission, SubmissionError, package_name, \
    unpack
from exp_assignment2.grading.run.truth import TruthServer
from exp_assignment2.launch_surface.viewer import FRAME_RATE_ENV as VIEWER_FRAME_RATE_ENV
from exp_assignment2.sim.ground_truth import SOCKET_ENV, TOPICS_ENV
from exp_assignment2.sim.releases import ENV as RELEASE_ENV
from exp_assignment2.sim.ball_setting import ENV as BALL_SCRIPT_ENV

START_SLACK = 120.0          # wall s on top of the duration: set-up, starting, ending
WORK_LIMIT = 2 * 1024 ** 3   # bytes the work directory may hold
# the environment a run starts with (the sandbox's is cleared)
PASSED_ENV = ('PATH', 'LANG', 'LC_ALL', 'EXP2_WS', 'EXP2_TEST_JOBS', 'EXP2_ROS_RELEASE')


class RunSettings(object):
    """What every run of a grading shares."""

    def __init__(self, profile, runs_dir, hidden=(), workspace=None,
                 real_time_factor=1.0, duration=None, version='', log=print):
        self.profile, self.runs_dir = profile, os.path.abspath(runs_dir)
        self.hidden = [os.path.abspath(h) for h in hidden]
        self.workspace = workspace or os.environ.get('EXP2_WS') or os.path.expanduser(
            '~/.cache/exp_assignment2_ws')
        self.real_time_factor = float(real_time_factor)
        self.duration = float(duration or profile['duration'])
        self.version, self.log = version, log


class Run(object):
    """One run of a :class:`~exp_assignment2.grading.plan.spec.RunSpec` (its
    commands exactly): ``go()`` does it and returns its result (also in run.json)."""

    def __init__(self, settings, spec, submission=None, stop_event=None):
        self.settings, self.spec = settings, spec
        # where the submission is here (a worker's copy), or where the spec says
        self.submission = submission or Submission(spec.name, spec.path, spec.kind)
        self.seed, self.label = spec.seed, spec.label
        self.dir = os.path.join(settings.runs_dir, self.label)
        self.work = os.path.join(self.dir, 'work')
        self.record = os.path.join(self.dir, 'record')
        self.sockets = os.path.join(self.dir, 'sockets')
        self.stop_event = stop_event or threading.Event()
        self.events, self.state = [], 'waiting'
        self._news = threading.Event()      # the driver said something
        self.result = None

    # the run's files
    def _fresh_dirs(self):
        shutil.rmtree(self.dir, ignore_errors=True)
        for path in (self.work, self.record, self.sockets,
                     os.path.join(self.work, 'home'), os.path.join(self.work, 'ros_home'),
                     os.path.join(self.work, 'original_env_bin')):
            os.makedirs(path, exist_ok=True)
        os.chmod(self.sockets, 0o755)

    def _plan(self, package_dir, more=(), root=None):
        """plan.json for the driver: the packages, the commands and their
        start plan (a spec without one: ``delay`` apart), each start's
        folder made a path in this run, inside the submission's ``root``."""
        delay = float(self.settings.profile['delay'])
        root = os.path.normpath(root or package_dir)
        plan_starts = [dict(s) for s in (self.spec.starts or starts.typed(self.spec.commands,
                                                                          delay))]
        for start in plan_starts:
            folder = os.path.normpath(os.path.join(root, start.get('cwd') or ''))
            start['dir'] = folder if (folder + os.sep).startswith(root + os.sep) else root
        plan = {'package': package_dir, 'more': list(more), 'root': root,
                'commands': self.spec.commands, 'delay': delay, 'starts': plan_starts,
                'logs': os.path.join(self.work, 'logs')}
        path = os.path.join(self.work, 'plan.json')
        with open(path, 'w') as f:
            json.dump(plan, f, indent=1)
        return path

    def _sandbox(self, real_time_factor):
        s, profile = self.settings, self.settings.profile
        ws = s.workspace
        env = {key: os.environ[key] for key in PASSED_ENV if key in os.environ}
        env.update({
            'HOME': os.path.join(self.work, 'home'), 'ROS_HOME': os.path.join(self.work, 'ros_home'),
            'ROS_MASTER_URI': 'http://localhost:11311', 'ROS_HOSTNAME': 'localhost',
            'TMPDIR': '/tmp', 'EXP2_WS': ws, 'EXP2_OVERLAY_ROOT': os.path.join(self.work, 'overlay'),
            'CCACHE_DISABLE': '1', 'PYTHONHASHSEED': str(self.seed), 'EXP2_SEED': str(self.seed),
            # nothing is installed in a sandbox (no network, no root): the grader did it before
            'EXP2_NO_INSTALL': '1',
            'PYTHONUNBUFFERED': '1', 'PYTHONDONTWRITEBYTECODE': '1',
            SOCKET_ENV: os.path.join(self.sockets, 'truth.sock'),
            TOPICS_ENV: ','.join(profile.get('record_topics') or []),
            'EXP2_REAL_TIME_FACTOR': '%g' % real_time_factor,
            # the viewers this package supplies (gzclient's rviz) draw at twice the
            # windows' capture pace: nobody watches the display live, and at rviz's
            # own 15 a second Gazebo's window cost more than the simulator
            VIEWER_FRAME_RATE_ENV: '2',
        })
        if self.spec.release:       # the release the student wrote for (ros_release.py)
            env[RELEASE_ENV] = self.spec.release
        if self.spec.ball_script:   # the course's ball, the same for everyone (episodes.py)
            env[BALL_SCRIPT_ENV] = json.dumps(self.spec.ball_script)
        env['PATH'] = '/usr/bin:/bin:/usr/sbin:/sbin'
        # the original-code shell writes its python launchers into the workspace:
        # a directory of the run's own is shown there (made once, outside, as
        # the mount's target)
        bin_dir = os.path.join(ws, 'original_env_bin')
        os.makedirs(bin_dir, exist_ok=True)
        return Sandbox(self.label, self.work, hidden=s.hidden + [os.path.expanduser('~')],
                       readonly=[ws, REPO], sockets=self.sockets,
                       binds=[(os.path.join(self.work, 'original_env_bin'), bin_dir)],
                       memory_mb=profile['memory_limit_mb'],
                       processes=profile['process_limit'], env=env)

    def go(self):
        """The run, start to record; whatever goes wrong in the grader on the
        way is this run's ``grader_error`` with its cause, never the grading's end."""
        started = time.time()
        spec = self.spec
        result = {'name': self.submission.name, 'label': self.label, 'seed': self.seed,
                  'version': self.settings.version, 'profile': self.settings.profile['name'],
                  'started': started, 'commands': list(spec.commands),
                  'commands_from': spec.commands_from, 'notes': list(spec.notes),
                  'readme_commands': list(spec.readme_commands),
                  'packages': list(spec.packages), 'release': spec.release,
                  'release_why': spec.release_why, 'episode': spec.episode}
        try:
            self._fresh_dirs()
            self._go(result)
        except Exception as exc:      # noqa: BLE001 -- a fault of the grader's, this run's only
            from exp_assignment2.grading.plan.planning import traceback_line
            result.update(verdict='grader_error', reason='the grader failed while running it '
                          '(a fault of the grader\'s, not the student\'s): %s'
                          % traceback_line(exc))
        return self._finish(result)

    def _packages(self, root):
        """(the main package's folder, the other built ones') under ``root``,
        as planned (else found here: a spec made by hand)."""
        if self.spec.build:
            dirs = [os.path.normpath(os.path.join(root, rel)) for rel in self.spec.build]
            if all(os.path.isfile(os.path.join(d, 'package.xml')) for d in dirs):
                return dirs[0], dirs[1:]
        found = packages_.find(root)
        if not found:
            raise SubmissionError('no package.xml in it (a catkin package has one)')
        main = packages_.main_package(found)
        listed, built = packages_.choose(found, main, self.spec.commands)
        return built[0].path, [p.path for p in built[1:]]

    def _go(self, result):
        spec = self.spec
        if spec.rejected:
            result.update(verdict='not_built', reason=spec.rejected)
            return
        failed = build_deps.install(spec.debian, self.settings.log)
        if failed:
            result['notes'].append('what the build needs from Debian could not be installed '
                                   'on this machine: %s' % failed)
        try:
            unpacked = unpack(self.submission, os.path.join(self.work, 'src'))
            package_dir, more = self._packages(unpacked.root)
        except SubmissionError as exc:
            result.update(verdict='not_built', reason='the submission: %s' % exc)
            return
        result['package'] = package_name(package_dir)
        rtf = self.settings.real_time_factor
        if rtf != 1.0:
            wall = waits_on_wall_clock(package_dir)
            if wall:
                result['notes'].append(
                    'run at real time, not %gx: the code waits on the wall clock (%s)'
                    % (rtf, ', '.join('%s:%d' % w for w in wall[:3])))
                rtf = 1.0
        result['real_time_factor_asked'] = rtf
        result['repeat_command'] = self.repeat_command()
        try:
            box = self._sandbox(rtf)
            result['limits'] = box.groups.notes or ['memory %d MB, %d processes' % (
                self.settings.profile['memory_limit_mb'], self.settings.profile['process_limit'])]
            truth = TruthServer(os.path.join(self.sockets, 'truth.sock'), self.record,
                                may_write=box.may_write)
            self._monitor(box, truth, self._plan(package_dir, more, unpacked.root), rtf, result)
        except SandboxError as exc:
            result.update(verdict='grader_error', reason=str(exc))

    def repeat_command(self):
        return 'bash tools/run grade %s --profile %s --seed %d --duration %g%s' % (
            getattr(self.submission, 'display_path', self.submission.path), self.settings.profile['name'], self.seed,
            self.settings.duration, ' --real-time-factor %g' % self.settings.real_time_factor
            if self.settings.real_time_factor != 1.0 else '')

    def _monitor(self, box, truth, plan, rtf, result):
        """Start the driver in the sandbox and watch until the run is over
        (why it ends: :func:`~exp_assignment2.grading.run.ending.end_reason`)."""
        events_path = os.path.join(self.record, 'events.jsonl')
        proc = box.start(['/usr/bin/python3', INSIDE, plan], stdout=subprocess.PIPE)
        events = self.events
        reader = threading.Thread(target=self._read_events,
                                  args=(proc, events, events_path, self._news), daemon=True)
        reader.start()
        duration = self.settings.duration
        t0 = time.monotonic()
        span = starts.span(self.spec.starts) if self.spec.starts else \
            len(self.spec.commands) * self.settings.profile['delay']
        facts = run_end.RunFacts(duration, duration / (rtf if rtf > 0 else 1.0) * 1.5 +
                                 START_SLACK, t0, span)
        required = logs.RequiredWatch(self.work)
        ending = None
        self.state = 'building'
        last_size_check = 0.0
        while proc.poll() is None:
            self._news.wait(0.25)       # a driver event, or the limits' next look
            self._news.clear()
            now = time.monotonic()
            if facts.built_at is None:
                built = next((e for e in events if e.get('event') == 'built'), None)
                if built is not None:
                    facts.built_at = now
                    self.state = 'running'
                    if built.get('rc') != 0:
                        result['ended_by'] = 'build_failed'
                        break
            if ending:
                if now - ending[1] > 40:        # the driver did not end its commands
                    break
                continue
            facts.cancelled = self.stop_event.is_set()
            facts.truth = truth.latest
            facts.all_exited = self._all_exited(events)
            if facts.built_at is not None and not facts.required_died:
                facts.required_died = required.death()
            if now - last_size_check > 5:
                last_size_check = now
                facts.over_disk = directory_size(self.work) > WORK_LIMIT
            reason = run_end.end_reason(facts, now)
            if reason:
                ending = (reason, now)
                result['ended_by'] = reason
                result['ended_at'] = truth.latest[0] if truth.latest else 0.0   # simulated s
                if reason == 'required_node_died':
                    result['required_node'] = facts.required_died
                result['cpu_s'], result['memory_mb'] = cpu.snapshot(box.groups.pids())
                result['log_sizes'] = log_sizes(self.work)
                self.state = 'ending'
                try:
                    proc.stdin.write('stop\n')
                    proc.stdin.flush()
                except (OSError, ValueError):
                    pass
        result.setdefault('ended_by', 'driver_exit')
        result.setdefault('log_sizes', log_sizes(self.work))
        result['all_gone'] = box.kill()
        result['peak_memory_mb'] = (box.groups.peak_memory() or 0) / 2 ** 20
        result['oom'] = box.groups.oom_killed()
        if result['all_gone']:
            box.groups.remove()
        reader.join(2.0)
        truth.close()
        result['truth'] = {'states': truth.states, 'frames': truth.frames,
                           'topics': truth.topics, 'dropped': truth.dropped,
                           'simulator': truth.simulator and truth.simulator[1],
                           'refused_peers': truth.refused,
                           'sim_time': truth.latest[0] if truth.latest else 0.0}
        result['real_time_factor'] = truth.real_time_factor()
        result['wall_time'] = time.monotonic() - t0
        result['sandbox_exit'] = proc.returncode
        result['events'] = events
        built = next((e for e in events if e.get('event') == 'built'), None)
        if built is not None:
            result['build'] = {'rc': built.get('rc'), 'error': built.get('error')}

    @staticmethod
    def _all_exited(events):
        started = {e['index'] for e in events if e.get('event') == 'started'}
        exited = {e['index'] for e in events if e.get('event') == 'exited'}
        return bool(started) and started <= exited

    @staticmethod
    def _read_events(proc, events, path, news):
        with open(path, 'w') as out:
            for line in proc.stdout:
                out.write(line)
                if len(events) > 10000:
                    continue
                try:
                    event = json.loads(line)
                except ValueError:
                    event = {'event': 'output', 'text': line.rstrip()[:500]}
                if isinstance(event, dict):
                    events.append(event)
                    news.set()

    def _finish(self, result):
        result.setdefault('duration', self.settings.duration)
        result.setdefault('ended_by', 'not_run')      # not unpacked, or no sandbox
        if 'verdict' not in result:
            try:
                result.update(verdicts.judge(self.work, self.record, result,
                                             self.settings.profile))
            except Exception as exc:      # noqa: BLE001 -- the grader's fault, this run's only
                from exp_assignment2.grading.plan.planning import traceback_line
                result.update(verdict='grader_error', reason='the grader failed while judging '
                              'it (a fault of the grader\'s, not the student\'s): %s'
                              % traceback_line(exc))
        if result.get('verdict') == 'not_built':
            result['reason'] = build_deps.said_by_rosdep(result.get('reason') or '',
                                                         result.get('notes') or [])
        result['finished'] = time.time()
        self.result = record.write(self.record, result)
        self.state = 'done'
        return self.result

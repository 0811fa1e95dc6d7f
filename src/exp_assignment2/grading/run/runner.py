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
import threading
import time
import uuid

from exp_assignment2.grading import record
from exp_assignment2.grading.judge import again
from exp_assignment2.grading.entry import build_deps
from exp_assignment2.grading.entry import packages as packages_
from exp_assignment2.grading.paths import ROOT
from exp_assignment2.grading.plan import starts
from exp_assignment2.grading.entry.submissions import Submission, SubmissionError, package_name, \
    unpack
from exp_assignment2.grading.run import ending
from exp_assignment2.grading.run import monitor
from exp_assignment2.grading.run.files import waits_on_wall_clock
from exp_assignment2.grading.run.sandbox import Sandbox, SandboxError
from exp_assignment2.grading.run.truth import TruthServer
from exp_assignment2.original_env import environment as original_env
from exp_assignment2.launch_surface.viewer import FRAME_RATE_ENV as VIEWER_FRAME_RATE_ENV
from exp_assignment2.sim.ground_truth import SOCKET_ENV, TOPICS_ENV
from exp_assignment2.sim.releases import ENV as RELEASE_ENV
from exp_assignment2.sim.ball_setting import ENV as BALL_SCRIPT_ENV

# the environment a run starts with (the sandbox's is cleared)
PASSED_ENV = ('PATH', 'LANG', 'LC_ALL', 'EXP2_WS', 'EXP2_TEST_JOBS', 'EXP2_ROS_RELEASE')


class RunSettings(object):
    """What every run of a grading shares."""

    def __init__(self, profile, runs_dir, hidden=(), workspace=None,
                 real_time_factor=1.0, duration=None, version='', log=print,
                 may_end_starved=False):
        self.profile, self.runs_dir = profile, os.path.abspath(runs_dir)
        # a first attempt that falls behind beside other runs ends early, to be run
        # again alone (run.ending's 'starved'), rather than at its end
        self.may_end_starved = may_end_starved
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
        self.submission = submission or Submission(spec.name, spec.path, spec.kind,
                                                   commit=(spec.git or {}).get('commit'))
        self.seed, self.label = spec.seed, spec.label
        self.starts_before = 0      # its starts on a worker before this attempt (dispatch)
        self.dir = os.path.join(settings.runs_dir, self.label)
        self.work = os.path.join(self.dir, 'work')
        self.record = os.path.join(self.dir, 'record')
        self.sockets = os.path.join(self.dir, 'sockets')
        self.stop_event = stop_event or threading.Event()
        self.events, self.state = [], 'waiting'
        self.news = threading.Event()       # the driver said something (monitor.watch)
        self.pace = None        # CPU s per simulated s as it runs (monitor.watch, cpu.Pace)
        self.result = None
        self.planned = None     # what the teacher's side planned it from (run.resume)
        self.notes = []         # the teacher's side's on it: why it was run again (run.admission)

    # the run's files
    def _fresh_dirs(self):
        record.unfinish(self.record)        # no record beside another attempt's files
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
            # the viewers this package supplies (gzclient's) draw at the windows'
            # capture pace, a picture a second: nobody watches the display live, and at
            # rviz's own 15 a second Gazebo's window cost more than the simulator (at 2 a
            # second the page kept as many pictures of it: 83 and 84 in 89 s)
            VIEWER_FRAME_RATE_ENV: '1',
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
        original_env.prepare(ws, env)       # what the sandbox reads there but cannot write
        return Sandbox(self.label, self.work, hidden=s.hidden + [os.path.expanduser('~')],
                       readonly=[ws, ROOT], sockets=self.sockets,
                       binds=[(os.path.join(self.work, 'original_env_bin'), bin_dir)],
                       memory_mb=profile['memory_limit_mb'],
                       processes=profile['process_limit'], env=env)

    def go(self):
        """The run, start to record; whatever goes wrong in the grader on the
        way is this run's ``grader_fault``, never the grading's end."""
        spec = self.spec
        result = record.RunRecord.new(
            self.submission.name, self.label, self.seed, version=self.settings.version,
            profile=self.settings.profile['name'], run_id=uuid.uuid4().hex,
            started=time.time(),
            commands=list(spec.commands), commands_from=spec.commands_from,
            notes=list(spec.notes), readme_commands=list(spec.readme_commands),
            packages=list(spec.packages), release=spec.release, release_why=spec.release_why,
            episode=spec.episode)
        if spec.git:        # the commit a git repository is graded at (git_entries.py)
            result['git'] = spec.git
        try:
            self._fresh_dirs()
            self._go(result)
        except Exception as exc:      # noqa: BLE001 -- a fault of the grader's, this run's only
            result['grader_fault'] = record.fault('failed while running it', exc)
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
        """The run's facts in ``result``: why it cannot be taken, or why its
        sandbox could not be made, or what its monitor saw."""
        spec = self.spec
        if spec.rejected:
            result['rejected'] = spec.rejected
            return
        failed = build_deps.install(spec.debian, self.settings.log)
        if failed:
            result['notes'].append('what the build needs from Debian could not be installed '
                                   'on this machine: %s' % failed)
        try:
            unpacked = unpack(self.submission, os.path.join(self.work, 'src'))
            package_dir, more = self._packages(unpacked.root)
        except SubmissionError as exc:
            result['rejected'] = 'the submission: %s' % exc
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
            monitor.watch(self, box, truth, self._plan(package_dir, more, unpacked.root), rtf,
                          result)
        except SandboxError as exc:
            result['sandbox_error'] = str(exc)

    def repeat_command(self):
        return 'bash tools/run grade %s --profile %s --seed %d --duration %g%s' % (
            getattr(self.submission, 'display_path', self.submission.path), self.settings.profile['name'], self.seed,
            self.settings.duration, ' --real-time-factor %g' % self.settings.real_time_factor
            if self.settings.real_time_factor != 1.0 else '')

    def _finish(self, result):
        """The verdict, decided on the run's facts (verdicts.RULES), and the record written."""
        result.setdefault('duration', self.settings.duration)
        result.setdefault('ended_by', ending.NOT_RUN)     # it never started
        again.decide(self.work, self.record, result, self.settings.profile)
        result['finished'] = time.time()
        self.result = record.write(self.record, result)
        self.state = 'done'
        return self.result

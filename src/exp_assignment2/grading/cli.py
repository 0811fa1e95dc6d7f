"""``bash tools/run grade SUBMISSIONS`` (and ``rosrun exp_assignment2 grade.py``):
every submission of a folder built, run in its sandbox and judged; one report.

    grade SUBMISSIONS [--out DIR] [--jobs K] [--duration S] [--repeat R] [--episodes N]
          [--profile dog|miro|FILE] [--real-time-factor F] [--seed N]
          [--only NAME ...] [--scheduler tcp://HOST:PORT] [--report-only]
          [--template DIR ...] [--base-share F] [--similarity-only]
    grade --calibrate [REF] [--episodes N] [--profile ...] [--out DIR]
"""
import argparse
import multiprocessing
import os
import signal
import sys

from exp_assignment2.grading.plan import planning
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.report import index as report
from exp_assignment2.grading.run import tasks
from exp_assignment2.grading.run.cluster import Cluster, ClusterError, lost_result, payload, \
    refused_result, rejected_result, unpack_result
from exp_assignment2.grading.plan.commands import TeacherFileError
from exp_assignment2.grading.progress import Progress
from exp_assignment2.grading.run.runner import Run, RunSettings
from exp_assignment2.grading.plan.spec import RunSpec
from exp_assignment2.grading.plan.planning import traceback_line
from exp_assignment2.grading.plan.submissions import SubmissionError

# 4: the report is written, but some runs could not be graded (grader_error: run them again)
EXIT_OK, EXIT_USAGE, EXIT_CLUSTER, EXIT_NOT_ALL_GRADED = 0, 2, 3, 4


def _interrupt(*_):
    raise KeyboardInterrupt()


def parse_args(argv):
    parser = argparse.ArgumentParser(prog='tools/run grade', description=__doc__.split('\n')[0])
    parser.add_argument('submissions', nargs='?', help='a folder of submissions (directories, '
                        '.zip, .tar.gz, .tgz), or one package directory')
    parser.add_argument('--out', help='the report directory (default: ./grading-report)')
    parser.add_argument('--jobs', type=int, help='runs at once (default: as many as keep '
                        'every run at real time on this machine)')
    # None: not given, so grading.yaml's value, else the profile's, holds (spec.settings)
    parser.add_argument('--duration', type=float, help='simulated s a run lasts '
                        '(default: grading.yaml\'s, else the profile\'s)')
    parser.add_argument('--repeat', type=int, default=1, help='runs of each submission, '
                        'with seeds 1..R (default 1)')
    parser.add_argument('--seed', type=int, default=1, help='the first run\'s seed')
    parser.add_argument('--episodes', type=int, help='runs of each submission, each on its own '
                        'seed of the course\'s ball when the profile scripts it (default: the '
                        'seeds its script lists, else 1)')
    parser.add_argument('--calibrate', nargs='?', const='', metavar='REF',
                        help='run a reference solution (default: the one this package ships) '
                        'and write a profile whose thresholds are its figures with margins')
    parser.add_argument('--profile', help='dog, miro, or a profile file (default: '
                        'grading.yaml\'s, else dog)')
    parser.add_argument('--real-time-factor', type=float,
                        help='simulated s per wall s (default: grading.yaml\'s, else 1, as '
                        'the code was written for)')
    parser.add_argument('--only', nargs='+', metavar='NAME', help='only these submissions')
    parser.add_argument('--scheduler', metavar='tcp://HOST:PORT',
                        help='run on the workers of this Dask scheduler (tools/run grade-worker)'
                        ' instead of this machine alone')
    parser.add_argument('--report-only', action='store_true',
                        help='make the report again from the runs already in --out')
    add_similarity_args(parser)
    args = parser.parse_args(argv)
    if not 0 < args.base_share <= 1:
        parser.error('--base-share: %r is not a share in (0, 1]' % args.base_share)
    if args.submissions is None and args.calibrate is None:
        parser.error('give a folder of submissions (or --calibrate)')
    for name in ('jobs', 'repeat', 'episodes'):
        value = getattr(args, name)
        if value is not None and not 1 <= value <= 64:
            parser.error('--%s: %d is not in 1..64' % (name, value))
    for name in ('duration', 'real_time_factor'):
        value = getattr(args, name)
        if value is not None and not (value == value and 0 <= value <= 100000):
            parser.error('--%s: %r is not a number of seconds or a factor'
                         % (name.replace('_', '-'), value))
    if args.duration is not None and args.duration <= 0:
        parser.error('--duration must be positive')
    return args


def default_jobs(profile):
    """As many runs as the cores keep at real time (the profile's measured cost)."""
    return max(1, int(multiprocessing.cpu_count() // float(profile['cpu_per_run'])))


def plan_runs(args, profile, out, log):
    """([Run] for every submission and repeat, in the folder's order; the profile)."""
    specs, profile, whence = planning.plan(args, out, tasks.package_version(), log)
    given = [key for key, where in sorted(whence.items()) if where == 'grading.yaml']
    if given:
        log('from grading.yaml: %s (the command line would be over it)' % ', '.join(given))
    runs = []
    for spec in specs:
        settings = RunSettings(spec.profile, os.path.join(out, 'runs'), hidden=spec.hidden,
                               real_time_factor=spec.real_time_factor, duration=spec.duration,
                               version=spec.version, log=log)
        runs.append(Run(settings, spec))
    return runs, profile


def default_out(submissions):
    """``./grading-report``, unless that is inside what is graded (a student
    running ``grade .`` in their package): then beside it, ``NAME-grading-report``."""
    out, folder = os.path.abspath('grading-report'), os.path.abspath(submissions)
    if out == folder or out.startswith(folder + os.sep):
        out = os.path.join(os.path.dirname(folder), os.path.basename(folder) + '-grading-report')
    return out


def in_next_release(run):
    """The run again in the next ROS release whose plugins behave otherwise
    for it, when its checks failed in a release it was not told (None: no
    other to try). ros_release.py; the better run counts (report.py)."""
    spec, result = run.spec, run.result or {}
    if not spec.releases_next or result.get('verdict') != 'failed_checks':
        return None
    data = spec.to_dict()
    release = data['releases_next'][0]
    data.update(release=release, releases_next=data['releases_next'][1:],
                label='%s-%s' % (spec.label, release),
                release_why='its checks failed in ROS %s (%s): run again in %s, whose Gazebo '
                            'plugins behave otherwise for it' % (
                                spec.release, spec.release_why, release))
    return Run(run.settings, RunSpec.from_dict(data))


def grade(runs, cluster, progress):
    """Every Run as a Dask task; Ctrl-C ends every run (on every worker) and returns."""
    from concurrent.futures import CancelledError
    from distributed import KilledWorker, wait
    version = cluster.version
    futures = {}

    def send(run):
        """The run as a Dask task (its future), or its grader_error (None)."""
        try:
            future = cluster.submit(payload(run, version))
        except Exception as exc:      # noqa: BLE001 -- the grader's fault, this run's only
            refused_result(run, 'the grader could not send it to a worker (a fault of the '
                           'grader\'s, not the student\'s): %s' % traceback_line(exc))
            return None
        futures[future] = run
        return future
    for run in runs:
        if run.spec.refused:       # the teacher's file is wrong about it, or the grader failed
            refused_result(run, run.spec.refused)
        elif run.spec.rejected:    # nothing to run: it does not unpack, it holds no package
            rejected_result(run, run.spec.rejected)
        else:
            send(run)
    pending = set(futures)
    try:
        while pending:
            cluster.poll_starts()
            for future in [f for f in pending if f.done()]:
                pending.discard(future)
                run = futures[future]
                cluster.poll_starts()
                try:
                    unpack_result(future.result(), run, cluster.started)
                except (KilledWorker, CancelledError, tasks.VersionMismatch, OSError,
                        RuntimeError) as exc:
                    lost_result(run, exc, cluster.started)
                except Exception as exc:      # noqa: BLE001 -- this run's grader_error only
                    refused_result(run, 'the grader failed with this run (a fault of the '
                                   'grader\'s, not the student\'s): %s' % traceback_line(exc),
                                   cluster.started.get(run.label) or [])
                again = in_next_release(run)
                if again is not None:       # its checks failed: as its student may have run it
                    runs.append(again)
                    progress.total += 1
                    pending.update(f for f in [send(again)] if f is not None)
            for future in pending:
                run = futures[future]
                if run.label in cluster.started and run.state == 'waiting':
                    run.state = 'running'
            progress.show(runs)
            try:        # until a run ends, or half a second for the progress line
                wait(list(pending), timeout=0.5, return_when='FIRST_COMPLETED')
            except TimeoutError:
                pass
        progress.show(runs)
    except KeyboardInterrupt:
        progress.line('Ctrl-C: ending every run')
        cluster.cancel(pending)
        raise


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    log = lambda text: print('[grade] ' + text, file=sys.stderr, flush=True)  # noqa: E731
    if args.calibrate is not None:      # a reference graded, its figures made a profile
        from exp_assignment2.grading.plan import calibration
        return calibration.main(args, main, log)
    out = os.path.abspath(args.out) if args.out else default_out(args.submissions)
    try:
        # the profile by the one precedence: --profile, grading.yaml's, dog
        if args.similarity_only:
            return similarity_step(args, out, log)
        profile = planning.read_settings(args)[1]['profile']
        if args.report_only:
            summaries = report.write(out, profile)
            log(summary_line(summaries, out))
            return EXIT_OK
        folder = os.path.abspath(args.submissions)
        if out == folder or out.startswith(folder + os.sep):
            raise SubmissionError('--out %s is inside the submissions folder, which is only '
                                  'ever read: choose another' % out)
        runs, profile = plan_runs(args, profile, out, log)
    except (profiles.ProfileError, TeacherFileError, SubmissionError) as exc:
        log(str(exc))
        return EXIT_USAGE
    if not runs:
        log('nothing to grade')
        return EXIT_USAGE
    os.makedirs(os.path.join(out, 'runs'), exist_ok=True)
    jobs = args.jobs or default_jobs(profile)
    try:
        cluster = Cluster(args.scheduler, jobs=jobs, log=log)
    except ClusterError as exc:
        log(str(exc))
        return EXIT_CLUSTER
    log('%d runs of %d submissions, %s, %g simulated s each, profile %s; report: %s'
        % (len(runs), len({r.submission.name for r in runs}),
           'on the workers of ' + args.scheduler if args.scheduler else '%d at once' % jobs,
           runs[0].settings.duration, profile['name'], out))
    progress = Progress(len(runs), jobs, extra=lambda: '%d workers' % cluster.worker_count())
    previous = signal.getsignal(signal.SIGTERM)
    signal.signal(signal.SIGTERM, _interrupt)
    try:
        grade(runs, cluster, progress)
    except KeyboardInterrupt:
        log('stopped: the report holds the runs that ended')
        report.write(out, profile)
        return 130
    finally:
        signal.signal(signal.SIGTERM, previous)
        progress.close()
        cluster.close()
    summaries = report.write(out, profile)
    if len(summaries) > 1:      # before the last lines, which name the pages
        similarity_step(args, out, log)
    log(summary_line(summaries, out))
    log(feedback_line(summaries, out))
    ungraded = sorted(n for n, s in summaries.items() if s['verdict'] == 'grader_error')
    if ungraded:
        log('not graded, through a fault of the grader\'s (grade them again with --only): %s'
            % ' '.join(ungraded))
        return EXIT_NOT_ALL_GRADED
    return EXIT_OK


def add_similarity_args(parser):
    """The similarity report's options (issue 42; docs/grading.md)."""
    parser.add_argument('--template', action='append', metavar='DIR',
                        help='code every student started from, never counted as shared '
                        '(repeatable; default: grading.yaml\'s template: list)')
    parser.add_argument('--base-share', type=float, default=0.1, metavar='F',
                        help='a passage in more than max(3, F x the class) submissions is '
                        'base code, never counted (default 0.1)')
    parser.add_argument('--similarity-only', action='store_true',
                        help='only the similarity report: nothing built or run')


def similarity_step(args, out, log):
    """The similarity report into ``out``; never changes a verdict or a score."""
    from exp_assignment2.grading.similarity import step as similarity_run
    folder = os.path.abspath(args.submissions)
    try:
        if out == folder or out.startswith(folder + os.sep):
            raise SubmissionError('--out %s is inside the submissions folder, which is only '
                                  'ever read: choose another' % out)
        teacher = planning.read_settings(args)[0]
        templates = similarity_run.templates_of(args, teacher, folder)
        similarity_run.run(folder, out, templates, args.base_share, args.only, log)
    except ImportError as exc:      # copydetect: tools/run grade installs it
        log('similarity: not made: %s' % exc)
        return EXIT_USAGE
    except (TeacherFileError, SubmissionError, profiles.ProfileError) as exc:
        log('similarity: %s' % exc)
        return EXIT_USAGE
    except Exception as exc:    # noqa: B902 -- the grades are written: a report's fault ends here
        log('similarity: failed: %s: %s' % (type(exc).__name__, exc))
        return 1
    return EXIT_OK


def feedback_line(summaries, out):
    """Where the students' pages are (one package: its own page)."""
    if len(summaries) == 1:
        return 'your feedback page: %s' % os.path.join(out, 'feedback', next(iter(summaries))
                                                        + '.html')
    return 'the students\' pages (no hidden check, no path of this machine): %s' % os.path.join(
        out, 'feedback')


def summary_line(summaries, out):
    import collections
    counts = collections.Counter(s['verdict'] for s in summaries.values())
    from exp_assignment2.grading.judge.verdicts import VERDICTS
    return 'graded %d submissions: %s; report: %s' % (
        len(summaries), ', '.join('%d %s' % (counts[v], v) for v in VERDICTS if counts[v]),
        os.path.join(out, 'index.html'))

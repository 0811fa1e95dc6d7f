"""``bash tools/run grade SUBMISSIONS`` (and ``rosrun exp_assignment2 grade.py``):
every submission of a folder built, run in its sandbox and judged; one report.

    grade SUBMISSIONS [--out DIR] [--jobs K] [--duration S] [--repeat R] [--episodes N]
          [--profile dog|miro|FILE] [--real-time-factor F] [--seed N]
          [--only NAME ...] [--scheduler tcp://HOST:PORT] [--report-only]
          [--template DIR ...] [--base-share F] [--similarity-only]
          [--deadline TIME] [--reference DIR ...]
    grade --calibrate [REF] [--episodes N] [--profile ...] [--out DIR]
    grade --fingerprint-template PROFILE.yaml --template DIR [--template DIR ...]
"""
import multiprocessing
import os
import sys

from exp_assignment2.grading.plan import busy_loops, camera_load
from exp_assignment2.grading.plan import planning
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.report import gradebook
from exp_assignment2.grading.report import index as report
from exp_assignment2.grading.report import resumed as report_resumed
from exp_assignment2.grading.run import tasks
from exp_assignment2.grading.run.admission import BUSY, Admission
from exp_assignment2.grading.run.cluster import Cluster, ClusterError
from exp_assignment2.grading.run.dispatch import grade
from exp_assignment2.grading.run.resume import Resume
from exp_assignment2.grading.run.stopping import Stopping
from exp_assignment2.grading.plan.commands import TeacherFileError
from exp_assignment2.grading.entry.copies import Copies
from exp_assignment2.grading.options import most_jobs, parse_args
from exp_assignment2.grading.progress import Progress
from exp_assignment2.grading.run.runner import Run, RunSettings
from exp_assignment2.grading.entry.submissions import SubmissionError
from exp_assignment2.grading.similarity import command as similarity_command

# 4: the report is written, but some runs could not be graded (grader_error: run them again)
EXIT_OK, EXIT_USAGE, EXIT_CLUSTER, EXIT_NOT_ALL_GRADED = 0, 2, 3, 4


def admission(args, profile, runs, copies, log):
    """When each run may start (run.admission): on this machine, when the cores
    its measured cost needs are free (a submission whose Python loops without
    waiting, plan.busy_loops, counted dearer until measured); on a Dask
    scheduler's workers, as they take them."""
    if args.scheduler:
        return Admission(None, profile['cpu_per_run'], len(runs))
    admitting = Admission(multiprocessing.cpu_count(), profile['cpu_per_run'], most_jobs(args))
    for name, where in sorted(busy_loops.of_runs(runs, copies).items()):
        admitting.expect_busy(name)
        log('%s: counted %g cores dearer until its run is measured: its Python loops without '
            'waiting (%s)' % (name, BUSY, ', '.join('%s:%d' % place for place in where[:3])))
    cameras = camera_load.of_runs(runs, copies)
    for name, frames in sorted(cameras.items()):
        admitting.expect_frames(name, frames)
    if len(set(cameras.values())) > 1:
        log('cameras of %s frames of 800 x 800 a second (their robot files): each run counted at '
            "the class's costs scaled to its camera until its own is measured"
            % _by_value(cameras))
    return admitting


def _by_value(values):
    """``30 (12 submissions), 1.8 (a, b)``: the most common value counted, the others named."""
    groups = {}
    for name, value in sorted(values.items()):
        groups.setdefault(round(value, 1), []).append(name)
    common = max(groups, key=lambda v: len(groups[v]))
    return ', '.join('%g (%s)' % (value, '%d submissions' % len(names) if value == common and
                                  len(names) > 3 else ', '.join(names))
                     for value, names in sorted(groups.items(), key=lambda g: -len(g[1])))


def plan_runs(args, out, log, read, submissions, copies):
    """([Run] for every submission and repeat, in the folder's order; the profile)
    from what was read once (planning.plan)."""
    specs, profile, whence = planning.plan(args, out, tasks.package_version(), log, read,
                                           submissions, copies)
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


def _outside(folder, out):
    """SubmissionError when the report would be written inside the folder graded."""
    if out == folder or out.startswith(folder + os.sep):
        raise SubmissionError('--out %s is inside the submissions folder, which is only '
                              'ever read: choose another' % out)


def default_out(submissions):
    """``./grading-report``, unless that is inside what is graded (a student
    running ``grade .`` in their package): then beside it, ``NAME-grading-report``."""
    out, folder = os.path.abspath('grading-report'), os.path.abspath(submissions)
    if out == folder or out.startswith(folder + os.sep):
        out = os.path.join(os.path.dirname(folder), os.path.basename(folder) + '-grading-report')
    return out


def main(argv=None):
    """The command line: grading.yaml read once, the folder discovered once,
    each submission copied once on the teacher's side (entry.copies), the
    report's index written once, after the similarity step."""
    args = parse_args(sys.argv[1:] if argv is None else argv)
    log = lambda text: print('[grade] ' + text, file=sys.stderr, flush=True)  # noqa: E731
    if args.calibrate is not None:      # a reference graded, its figures made a profile
        from exp_assignment2.grading.plan import calibration
        return calibration.main(args, main, log)
    if args.fingerprint_template:       # a template's fingerprints kept in a profile
        return similarity_command.fingerprint_template(args, log)
    out = os.path.abspath(args.out) if args.out else default_out(args.submissions)
    if args.similarity_only:
        return similarity_only(args, out, log)
    try:
        # the profile by the one precedence: --profile, grading.yaml's, dog
        read = planning.read_settings(args)
        if args.report_only:
            return report_only(out, read, log)
        _outside(os.path.abspath(args.submissions), out)
        submissions = planning.entries(args, log)
    except (profiles.ProfileError, TeacherFileError, SubmissionError) as exc:
        log(str(exc))
        return EXIT_USAGE
    with Copies() as copies:
        return _grade(args, out, log, read, submissions, copies)


def _grade(args, out, log, read, submissions, copies):
    try:
        runs, profile = plan_runs(args, out, log, read, submissions, copies)
    except (profiles.ProfileError, TeacherFileError, SubmissionError) as exc:
        log(str(exc))
        return EXIT_USAGE
    if not runs:
        log('nothing to grade')
        return EXIT_USAGE
    os.makedirs(os.path.join(out, 'runs'), exist_ok=True)
    jobs, admitting = most_jobs(args), admission(args, profile, runs, copies, log)
    try:
        cluster = Cluster(args.scheduler, jobs=jobs, log=log)
    except ClusterError as exc:
        log(str(exc))
        return EXIT_CLUSTER
    log('%d runs of %d submissions, %s, %g simulated s each, profile %s; report: %s'
        % (len(runs), len({r.submission.name for r in runs}),
           'on the workers of ' + args.scheduler if args.scheduler else
           '%d at once to start with, as many as their measured cost lets %d cores keep at '
           'real time from then on (at most %d)' % (
               admitting.most_at_once(runs[0].settings.real_time_factor),
               admitting.cores, jobs), runs[0].settings.duration, profile['name'], out))
    progress = Progress(len(runs), jobs, extra=lambda: '%d workers' % cluster.worker_count())
    resume = Resume(os.path.join(out, 'runs'), copies, log)
    with Stopping() as stopping:
        try:
            stopped = grade(runs, cluster, progress, copies, stopping, resume, admitting)
        except KeyboardInterrupt:
            stopped = [r for r in runs if r.state != 'done']
            stopping.asked = stopping.asked or 1
        finally:
            progress.close()
            cluster.close()
    if stopping.asked:
        report_resumed.write(out, resume.summary(runs, stopped))
        log('stopped: the report holds the runs that ended; %d not run: grade again with the '
            'same --out to run them (the others are kept)' % len(stopped))
        report.write(out, profile, teacher=read[0])
        return 130
    dropped = resume.drop_others(runs)
    if dropped:
        log('taken away: %d runs of an earlier plan of these submissions (%s)'
            % (len(dropped), ', '.join(dropped)))
    report_resumed.write(out, resume.summary(runs, []))
    if len({r.spec.name for r in runs}) > 1:    # read by the index, written next
        try:
            similarity_command.step(args, out, log, read, submissions, copies)
        except KeyboardInterrupt:
            log('stopped: the report holds every run, without the similarity column')
            report.write(out, profile, teacher=read[0])
            return 130
    summaries = report.write(out, profile, teacher=read[0])
    if gradebook.missing_line(summaries, read[0]):
        log(gradebook.missing_line(summaries, read[0]))
    log(summary_line(summaries, out))
    log(feedback_line(summaries, out))
    ungraded = sorted(n for n, s in summaries.items() if s['verdict'] == 'grader_error')
    if ungraded:
        log('not graded, through a fault of the grader\'s (grade them again with --only): %s'
            % ' '.join(ungraded))
        return EXIT_NOT_ALL_GRADED
    return EXIT_OK


def report_only(out, read, log):
    """``--report-only``: every run of ``out`` judged again from its records
    with the profile chosen (and grading.yaml's roles of each submission),
    nothing run; the report written, with what changed (report.changes)."""
    from exp_assignment2.grading.judge import again
    from exp_assignment2.grading.report import changes
    teacher, chosen, _ = read
    profile, own = chosen['profile'], teacher.get('submissions') or {}
    runs_dir = os.path.join(out, 'runs')
    judged = again.all_rejudged(runs_dir, report.load_runs(runs_dir), lambda name: (
        profiles.with_teacher_roles(profile, (own.get(name) or {}).get('roles'))))
    summaries = report.write(out, profile, runs=judged, teacher=teacher)
    log('judged %d runs again from their records, with profile %s' % (len(judged),
                                                                      profile['name']))
    if gradebook.missing_line(summaries, teacher):
        log(gradebook.missing_line(summaries, teacher))
    said = changes.terminal_line(out)
    if said:
        log(said)
    log(summary_line(summaries, out))
    return EXIT_OK


def similarity_only(args, out, log):
    """``--similarity-only``: grading.yaml read and the folder discovered for
    the similarity step alone; the index of a grading's report there written
    again with its column."""
    from exp_assignment2.grading.entry.submissions import discover
    try:
        _outside(os.path.abspath(args.submissions), out)
        read = planning.read_settings(args)
        submissions = discover(args.submissions)[0]
    except (TeacherFileError, SubmissionError, profiles.ProfileError) as exc:
        log('similarity: %s' % exc)
        return EXIT_USAGE
    with Copies() as copies:
        code = similarity_command.step(args, out, log, read, submissions, copies)
    if code == EXIT_OK and os.path.isfile(os.path.join(out, 'index.html')):
        report.write_index(out, read[1]['profile'])
    return code


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

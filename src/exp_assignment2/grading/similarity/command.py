"""The similarity report's part of ``grade``'s command line (no ROS): its
options, and the step a grading runs (or ``--similarity-only`` alone), whose
exit code is grade's: 0 made, 2 a mistake in what was asked, 1 it failed
(never a grade's fault: the grades are written without it)."""
import os

from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.entry.copies import Copies
from exp_assignment2.grading.entry.submissions import SubmissionError
from exp_assignment2.grading.plan.teacher_file import TeacherFileError
from exp_assignment2.grading.similarity import step as similarity_run
from exp_assignment2.grading.similarity import template_prints

USAGE = 2


def add_args(parser):
    """The similarity report's options (issue 42; docs/grading.md)."""
    parser.add_argument('--template', action='append', metavar='DIR',
                        help='code every student started from, never counted as shared '
                        '(repeatable; default: grading.yaml\'s template: list)')
    parser.add_argument('--base-share', type=float, default=0.1, metavar='F',
                        help='a passage in more than max(3, F x the class) submissions is '
                        'base code, never counted (default 0.1)')
    parser.add_argument('--similarity-only', action='store_true',
                        help='only the similarity report: nothing built or run')
    parser.add_argument('--reference', action='append', metavar='DIR',
                        help='a folder of earlier years\' submissions the class is compared '
                        'with (repeatable; never compared among themselves)')
    parser.add_argument('--fingerprint-template', metavar='PROFILE.yaml',
                        help='write the --template folders\' fingerprints into this profile '
                        'file: a grading with it leaves them out, with no --template')


def step(args, out, log, read, submissions, copies):
    """The similarity report of ``submissions`` (their ``copies``) into ``out``,
    with ``read`` (planning.read_settings'); never changes a verdict or a score."""
    def make():
        teacher, chosen, _ = read
        templates = similarity_run.templates_of(args, teacher, os.path.abspath(args.submissions))
        runs_dir = os.path.join(out, 'runs')     # a grading's: the packages its runs built
        similarity_run.run(submissions, out, templates, copies, args.base_share, args.only, log,
                           references=similarity_run.references_of(args), settings={
                               'teacher': teacher, 'profile': chosen['profile'],
                               'deadline': args.deadline,
                               'runs_dir': runs_dir if os.path.isdir(runs_dir) else None,
                               'template_prints': template_prints.of_profile(
                                   chosen.get('profile_source'))})
        return 0
    try:
        return _asked('similarity', log, make)
    except Exception as exc:    # noqa: B902 -- a fault of the similarity's costs no grade
        log('similarity: failed: %s: %s' % (type(exc).__name__, exc))
        return 1


def fingerprint_template(args, log):
    """``--fingerprint-template PROFILE``: the ``--template`` folders' (or
    archives') fingerprints written into the profile file (0; 2: a mistake)."""
    path = args.fingerprint_template
    if not args.template:
        log('--fingerprint-template: give the template with --template DIR (repeatable)')
        return USAGE
    if not os.path.isfile(path):
        log('--fingerprint-template: %s is not a profile file (start one with "base: dog")'
            % path)
        return USAGE

    def write():
        templates = similarity_run.templates_of(args, {}, os.getcwd())
        with Copies() as copies:
            keys = similarity_run.template_keys(similarity_run.Reader(copies), templates)[0]
        if not keys:
            log('--fingerprint-template: no code to fingerprint in %s' % ', '.join(templates))
            return USAGE
        template_prints.write_into(path, keys, templates)
        log('%d fingerprints of %s written into %s: a grading with this profile leaves them '
            'out of every share' % (len(keys), ', '.join(templates), path))
        return 0
    return _asked('--fingerprint-template', log, write)


def _asked(what, log, action):
    """``action()``'s exit code, or USAGE with one line for what cannot be
    done as asked: a mistake in it, or copydetect missing."""
    try:
        return action()
    except ImportError as exc:      # copydetect: tools/run grade installs it
        log('%s: not made: %s' % (what, exc))
    except (TeacherFileError, SubmissionError, profiles.ProfileError) as exc:
        log('%s: %s' % (what, exc))
    return USAGE

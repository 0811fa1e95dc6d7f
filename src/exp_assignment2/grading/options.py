"""The grade command's options: what ``tools/run grade --help`` says, each value
checked before anything is read or run (no ROS)."""
import argparse
import multiprocessing

from exp_assignment2.grading.plan.commands import TeacherFileError
from exp_assignment2.grading.similarity import command as similarity_command

DESCRIPTION = 'every submission of a folder built, run in its sandbox and judged; one report'


def parse_args(argv):
    parser = argparse.ArgumentParser(prog='tools/run grade', description=DESCRIPTION)
    parser.add_argument('submissions', nargs='?', help='a folder of submissions (directories, '
                        '.zip, .tar.gz, .tgz), or one package directory')
    parser.add_argument('--out', help='the report directory (default: ./grading-report)')
    parser.add_argument('--jobs', type=int, help='the most runs at once (default: %d a '
                        'core); how many do run at once is what their measured cost lets the '
                        'cores keep at real time' % RUNS_PER_CORE)
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
                        help='make the report again from the runs already in --out, each '
                        'judged again with the profile (a changed threshold: whose marks '
                        'changed, in changes.html)')
    parser.add_argument('--deadline', metavar='TIME',
                        help='a git repository is graded at its last commit before TIME (ISO '
                        '8601: 2025-03-01T23:59, local time unless +01:00 or Z; default: '
                        'grading.yaml\'s deadline, else its checked-out commit)')
    similarity_command.add_args(parser)
    args = parser.parse_args(argv)
    if args.deadline is not None:
        from exp_assignment2.grading.entry import deadlines
        try:
            args.deadline = deadlines.parse_time(args.deadline, '--deadline')
        except TeacherFileError as exc:
            parser.error(str(exc))
    if not 0 < args.base_share <= 1:
        parser.error('--base-share: %r is not a share in (0, 1]' % args.base_share)
    if args.submissions is None and args.calibrate is None and not args.fingerprint_template:
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


# the most runs at once by default, a core (a run costs more than a quarter of one); how
# many do run at once is what their measured cost lets the cores keep at real time (admission)
RUNS_PER_CORE = 4


def most_jobs(args):
    """The most runs at once on this machine: ``--jobs``, else RUNS_PER_CORE a core."""
    return args.jobs or RUNS_PER_CORE * multiprocessing.cpu_count()

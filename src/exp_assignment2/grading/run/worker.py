"""``bash tools/run grade-worker tcp://HOST:PORT [--runs K] [DASK-WORKER OPTIONS]``:
this machine takes grading runs from a teacher's Dask scheduler.

It starts Debian's ``dask-worker`` with K threads and the resource
``runs=K`` (each grading task asks for one, so at most K run at once here),
named after the machine. Options after ``--runs`` go to dask-worker as they
are (e.g. ``--no-nanny``). ``tools/run`` has set the machine up first, as for
``main``, and installed what a submission's build and run need.
"""
import argparse
import os
import shutil
import socket
import sys

from exp_assignment2.grading.run.dask_settings import quiet_worker_environment
from exp_assignment2.grading.run.tasks import package_version


def main(argv=None):
    parser = argparse.ArgumentParser(prog='tools/run grade-worker',
                                     description=__doc__.split('\n')[0])
    parser.add_argument('scheduler', help='the teacher\'s scheduler, tcp://HOST:PORT')
    parser.add_argument('--runs', type=int, default=max(1, (os.cpu_count() or 2) // 2),
                        help='runs at once on this machine (default: a run per two cores)')
    args, rest = parser.parse_known_args(sys.argv[1:] if argv is None else argv)
    if not 1 <= args.runs <= 64:
        parser.error('--runs: %d is not in 1..64' % args.runs)
    program = shutil.which('dask-worker')
    if not program:
        print('[grade-worker] dask-worker is not installed (python3-distributed)',
              file=sys.stderr)
        return 1
    name = '%s-%d' % (socket.gethostname(), os.getpid())
    print('[grade-worker] %s: exp_assignment2 %s, at most %d runs at once, scheduler %s'
          % (name, package_version(), args.runs, args.scheduler), file=sys.stderr, flush=True)
    os.environ.update(quiet_worker_environment())
    os.execv(sys.executable, [sys.executable, program, args.scheduler, '--nthreads',
                              str(args.runs), '--resources', 'runs=%d' % args.runs,
                              '--name', name, '--no-dashboard'] + rest)


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
"""The grader's benchmark: ``bash tools/run bench grade [--jobs 1 2 3 4]
[--duration 200] [--count 10] [--scheduler tcp://HOST:PORT] [--dask K]``.

It grades the fixture folder (test/grading_fixtures.py, topped up with
copies of the dog that works to ``--count`` submissions) once per ``--jobs``
value and prints, for each: the wall time, submissions per hour, every run's
achieved real-time factor, whether the verdicts are the same as at the first
``--jobs`` value, and for one run of the dog that works its CPU by process
kind (simulator, ROS, the student's nodes, the grader's driver) and memory.
The goal on a 2-core machine: ten submissions of 200 simulated seconds in
at most 12 minutes of wall time, every run at a factor of at least 0.95.

``--scheduler ADDRESS`` grades through that Dask scheduler's workers instead
(the same figures). ``--dask K`` measures the scaling table's row on this
machine: it starts a scheduler and one worker taking K runs, grades, then two
workers taking K/2 each, grades again, and prints both.
Run it on an otherwise idle machine: it measures wall time.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(REPO, 'test'))
import grading_fixtures  # noqa: E402


def make_folder(dest, count):
    grading_fixtures.make_folder(dest)
    names = sorted(os.listdir(dest))
    for i in range(max(0, count - len(names))):
        shutil.copytree(os.path.join(dest, 'works'), os.path.join(dest, 'works_%d' % (i + 2)))
    return dest


def grade(folder, out, jobs, duration, rtf, scheduler=None):
    started = time.monotonic()
    where = ['--scheduler', scheduler] if scheduler else ['--jobs', str(jobs)]
    proc = subprocess.run([sys.executable, os.path.join(REPO, 'scripts', 'grade.py'), folder,
                           '--out', out, '--duration', str(duration),
                           '--real-time-factor', str(rtf)] + where,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True)
    wall = time.monotonic() - started
    if proc.returncode != 0:
        print(proc.stdout[-3000:])
        raise SystemExit('grading failed (exit %d)' % proc.returncode)
    with open(os.path.join(out, 'report.json')) as f:
        return wall, json.load(f), proc.stdout.strip().splitlines()[-1]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--jobs', type=int, nargs='+', default=[1, 2, 3, 4])
    parser.add_argument('--duration', type=float, default=200.0)
    parser.add_argument('--count', type=int, default=10)
    parser.add_argument('--real-time-factor', type=float, default=1.0)
    parser.add_argument('--keep', help='keep the reports in this directory')
    parser.add_argument('--scheduler', help='grade through this Dask scheduler\'s workers')
    parser.add_argument('--dask', type=int, metavar='K',
                        help='one worker with K runs against two with K/2 each, here')
    args = parser.parse_args(argv)
    scratch = args.keep or tempfile.mkdtemp(prefix='bench-grade-')
    folder = make_folder(os.path.join(scratch, 'class'), args.count)
    count = len(os.listdir(folder))
    print('grading %d submissions of %g simulated s at real_time_factor %g, %d cores'
          % (count, args.duration, args.real_time_factor, os.cpu_count()))
    print('%4s %8s %10s %8s %8s %8s %s' % ('jobs', 'wall s', 'subs/hour', 'rtf min',
                                          'rtf med', 'same', 'verdicts'))
    first, detail = None, None
    if args.dask:
        return dask_rows(args, folder, scratch, count)
    for jobs in ([0] if args.scheduler else args.jobs):
        wall, report, summary = grade(folder, os.path.join(scratch, 'jobs%d' % jobs), jobs,
                                      args.duration, args.real_time_factor, args.scheduler)
        verdicts = {s['name']: s['verdict'] for s in report['submissions']}
        first = first or verdicts
        factors = [r['real_time_factor'] for r in report['runs'] if r.get('real_time_factor')]
        print('%4s %8.0f %10.1f %8.2f %8.2f %8s %s' % (
            jobs or 'dask', wall, count * 3600.0 / wall, min(factors), statistics.median(factors),
            'yes' if verdicts == first else 'NO', summary.split(': ', 1)[-1].split(';')[0]))
        print('     each run\'s real-time factor: ' + ', '.join(
            '%s %.2f' % (r['label'], r['real_time_factor']) for r in report['runs']
            if r.get('real_time_factor')))
        works = next((r for r in report['runs'] if r['label'] == 'works'), None)
        if works and detail is None:
            detail = (jobs, works)
    if detail:
        jobs, works = detail
        print('one run of the dog that works (jobs %d): wall %.0f s, simulated %.0f s, '
              'peak memory of the sandbox %.0f MB' % (jobs, works['wall_time'],
                                                       works['truth']['sim_time'],
                                                       works['peak_memory_mb']))
        for kind in sorted(works.get('cpu_s') or {}):
            print('  %-10s CPU %6.1f s  (%.2f of a core)  resident %6.0f MB' % (
                kind, works['cpu_s'][kind], works['cpu_s'][kind] / max(1.0, works['wall_time']),
                works['memory_mb'].get(kind, 0)))
    print('reports in %s' % scratch)


def _row(label, wall, report, count):
    factors = [r['real_time_factor'] for r in report['runs'] if r.get('real_time_factor')]
    workers = {r['workers'][-1] for r in report['runs'] if r.get('workers')}
    print('%-22s %8.0f %10.1f %8.2f %8.2f %8d' % (label, wall, count * 3600.0 / wall,
                                                  min(factors), statistics.median(factors),
                                                  len(workers)))


def dask_rows(args, folder, scratch, count):
    """The scaling row: one worker with K runs, then two with K/2 each."""
    import socket

    def free_port():
        with socket.socket() as s:
            s.bind(('127.0.0.1', 0))
            return s.getsockname()[1]
    port = free_port()
    address = 'tcp://127.0.0.1:%d' % port
    scheduler = subprocess.Popen(['dask-scheduler', '--host', '127.0.0.1', '--port', str(port),
                                  '--dashboard-address', '127.0.0.1:%d' % free_port()],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                 start_new_session=True)
    print('%-22s %8s %10s %8s %8s %8s' % ('workers x runs', 'wall s', 'subs/hour', 'rtf min',
                                          'rtf med', 'used'))
    try:
        for layout in ([args.dask], [args.dask // 2] * 2):
            workers = [subprocess.Popen([sys.executable, '-m', 'exp_assignment2.grading.worker',
                                         address, '--runs', str(k), '--no-nanny'],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                        start_new_session=True) for k in layout]
            try:
                _wait_workers(address, len(layout))
                wall, report, _ = grade(folder, os.path.join(scratch, 'dask-%d' % len(layout)),
                                        0, args.duration, args.real_time_factor, address)
                _row('%d x %d' % (len(layout), layout[0]), wall, report, count)
            finally:
                for worker in workers:
                    os.killpg(worker.pid, 9)
                    worker.wait()
    finally:
        os.killpg(scheduler.pid, 9)
    print('reports in %s' % scratch)


def _wait_workers(address, count, timeout=120):
    from distributed import Client
    deadline = time.monotonic() + timeout
    with Client(address, timeout=10) as client:
        while len(client.scheduler_info()['workers']) != count:
            if time.monotonic() > deadline:
                raise SystemExit('the workers did not come up')
            time.sleep(0.5)


if __name__ == '__main__':
    main(sys.argv[1:])

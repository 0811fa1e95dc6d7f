#!/usr/bin/env python3
"""The grader's benchmark: ``bash tools/run bench grade [--count 10]
[--duration 200] [--jobs K ...] [--fixtures] [--scheduler tcp://HOST:PORT] [--dask K]``.

By default it grades a class: ``--count`` copies of a submission shaped like
the real ones (test/course_shaped.py's ``make_course_shaped``: the course
robot's 800 x 800 camera at 30 Hz, Gazebo's window, a node that decodes,
blurs and searches every frame and ``cv2.imshow``s it with the circle drawn,
a SMACH state machine), each run with its display. ``--fixtures`` grades the grader's
fixture folder instead, topped up with copies of the dog that works.

For each ``--jobs`` value (default: none given, the grader's own default) it
prints the wall time, submissions per hour, every run's achieved real-time
factor and whether the verdicts are the same as at the first value; then,
over the runs of the first value, the CPU a run keeps busy by process kind
(simulator, display, viewer: gzclient and rviz, student, ROS, grader), in
cores at real time (CPU s per simulated s, of the processes alive at the
run's end), and the default ``--jobs`` that figure leads to on this machine (the profile's
``cpu_per_run``). The goal on a 2-core machine: ten submissions of 200
simulated seconds in at most 12 minutes of wall time, every run at a factor
of at least 0.95.

``--scheduler ADDRESS`` grades through that Dask scheduler's workers instead
(the same figures). ``--dask K`` measures the scaling table's row on this
machine: it starts a scheduler and one worker taking K runs, grades, then two
workers taking K/2 each, grades again, and prints both.
Run it on an otherwise idle machine: it measures wall time and CPU.
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
import course_shaped  # noqa: E402
import grading_fixtures  # noqa: E402


KINDS = ('simulator', 'display', 'viewer', 'student', 'ROS', 'grader')
GOAL = (10, 200.0, 12 * 60.0, 0.95)     # runs, simulated s each, wall s, least factor


def make_folder(dest, count, fixtures=False):
    """``count`` copies of the course-shaped submission; with ``fixtures``, the
    fixture folder topped up with copies of the dog that works."""
    if not fixtures:
        os.makedirs(dest)
        for i in range(count):
            course_shaped.make_course_shaped(os.path.join(dest, 'student_%02d' % (i + 1)))
        return dest
    grading_fixtures.make_folder(dest)
    names = sorted(os.listdir(dest))
    for i in range(max(0, count - len(names))):
        shutil.copytree(os.path.join(dest, 'works'), os.path.join(dest, 'works_%d' % (i + 2)))
    return dest


def cpu_per_run(runs):
    """{kind: [cores]} over the runs that ran: each kind's CPU s per simulated
    s, the cores it keeps busy at real time (a starved run's too)."""
    out = {kind: [] for kind in KINDS + ('all',)}
    for run in runs:
        cpu, sim = run.get('cpu_s') or {}, (run.get('truth') or {}).get('sim_time') or 0.0
        if not cpu or sim <= 0:
            continue
        for kind in KINDS:
            out[kind].append(cpu.get(kind, 0.0) / sim)
        out['all'].append(sum(cpu.values()) / sim)
    return out


def print_cpu(runs, jobs, profile):
    per_kind = cpu_per_run(runs)
    if not per_kind['all']:
        print('no run reported its CPU')
        return
    print('CPU per run by process kind, in cores at real time (CPU s per simulated s; '
          'mean of %d runs at --jobs %s, min-max):' % (len(per_kind['all']), jobs or 'default'))
    for kind in KINDS + ('all',):
        values = per_kind[kind]
        print('  %-10s %5.2f  (%.2f-%.2f)' % (kind, statistics.mean(values), min(values),
                                               max(values)))
    measured = statistics.mean(per_kind['all'])
    cores = os.cpu_count()
    print('measured cpu_per_run %.2f -> default --jobs on %d cores: %d (the %s profile says '
          'cpu_per_run %g -> %d)' % (measured, cores, max(1, int(cores // measured)),
                                     profile['name'], profile['cpu_per_run'],
                                     max(1, int(cores // float(profile['cpu_per_run'])))))
    memory = [r.get('peak_memory_mb') for r in runs if r.get('peak_memory_mb')]
    if memory:
        print('peak memory of a sandbox: %.0f MB (median), %.0f MB (max)' % (
            statistics.median(memory), max(memory)))


def grade(folder, out, jobs, duration, rtf, scheduler=None):
    shutil.rmtree(out, ignore_errors=True)      # from nothing: grade keeps the runs there
    started = time.monotonic()
    where = ['--scheduler', scheduler] if scheduler else ['--jobs', str(jobs)] if jobs else []
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
    parser.add_argument('--jobs', type=int, nargs='+', default=[None],
                        help='runs at once, one grading each (default: the grader\'s default)')
    parser.add_argument('--duration', type=float, default=GOAL[1])
    parser.add_argument('--count', type=int, default=GOAL[0])
    parser.add_argument('--real-time-factor', type=float, default=1.0)
    parser.add_argument('--fixtures', action='store_true',
                        help='the grader\'s fixture folder, not a class of course-shaped ones')
    parser.add_argument('--keep', help='keep the reports in this directory')
    parser.add_argument('--scheduler', help='grade through this Dask scheduler\'s workers')
    parser.add_argument('--dask', type=int, metavar='K',
                        help='one worker with K runs against two with K/2 each, here')
    args = parser.parse_args(argv)
    scratch = args.keep or tempfile.mkdtemp(prefix='bench-grade-')
    folder = make_folder(os.path.join(scratch, 'class'), args.count, args.fixtures)
    count = len(os.listdir(folder))
    print('grading %d submissions (%s) of %g simulated s at real_time_factor %g, %d cores' % (
        count, 'the fixture folder' if args.fixtures else
        'course-shaped: 800 x 800 camera at 30 Hz, Gazebo\'s window, imshow of every frame, SMACH',
        args.duration, args.real_time_factor, os.cpu_count()))
    if args.dask:
        return dask_rows(args, folder, scratch, count)
    print('%7s %8s %10s %8s %8s %8s %s' % ('jobs', 'wall s', 'subs/hour', 'rtf min',
                                           'rtf med', 'same', 'verdicts'))
    first, detail = None, None
    for jobs in ([None] if args.scheduler else args.jobs):
        wall, report, summary = grade(folder, os.path.join(scratch, 'jobs%s' % (jobs or '')),
                                      jobs, args.duration, args.real_time_factor,
                                      args.scheduler)
        verdicts = {s['name']: s['verdict'] for s in report['submissions']}
        first = first or verdicts
        factors = [r['real_time_factor'] for r in report['runs'] if r.get('real_time_factor')]
        print('%7s %8.0f %10.1f %8.2f %8.2f %8s %s' % (
            'dask' if args.scheduler else jobs or 'default', wall, count * 3600.0 / wall,
            min(factors or [0]), statistics.median(factors or [0]),
            'yes' if verdicts == first else 'NO', summary.split(': ', 1)[-1].split(';')[0]))
        print('     each run\'s real-time factor: ' + ', '.join(
            '%s %.2f' % (r['label'], r['real_time_factor']) for r in report['runs']
            if r.get('real_time_factor')))
        if (count, args.duration) == GOAL[:2] and args.real_time_factor == 1.0:
            met = wall <= GOAL[2] and factors and min(factors) >= GOAL[3] and \
                len(factors) == count
            print('     the goal (%d x %g s in %g min, every run at >= %g): %s' % (
                GOAL[0], GOAL[1], GOAL[2] / 60, GOAL[3], 'met' if met else 'NOT met'))
        if detail is None:
            detail = (jobs, report)
    if detail:
        jobs, report = detail
        print_cpu(report['runs'], jobs, report['profile'])
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
            workers = [subprocess.Popen([sys.executable, '-m', 'exp_assignment2.grading.run.worker',
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

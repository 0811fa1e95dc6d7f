#!/usr/bin/env python3
"""The grader's benchmark: ``bash tools/run bench grade [--jobs 1 2 3 4]
[--duration 200] [--count 10]``.

It grades the fixture folder (test/grading_fixtures.py, topped up with
copies of the dog that works to ``--count`` submissions) once per ``--jobs``
value and prints, for each: the wall time, submissions per hour, every run's
achieved real-time factor, whether the verdicts are the same as at the first
``--jobs`` value, and for one run of the dog that works its CPU by process
kind (simulator, ROS, the student's nodes, the grader's driver) and memory.
The goal on a 2-core machine: ten submissions of 200 simulated seconds in
at most 12 minutes of wall time, every run at a factor of at least 0.95.
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


def grade(folder, out, jobs, duration, rtf):
    started = time.monotonic()
    proc = subprocess.run([sys.executable, os.path.join(REPO, 'scripts', 'grade.py'), folder,
                           '--out', out, '--jobs', str(jobs), '--duration', str(duration),
                           '--real-time-factor', str(rtf)],
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
    args = parser.parse_args(argv)
    scratch = args.keep or tempfile.mkdtemp(prefix='bench-grade-')
    folder = make_folder(os.path.join(scratch, 'class'), args.count)
    count = len(os.listdir(folder))
    print('grading %d submissions of %g simulated s at real_time_factor %g, %d cores'
          % (count, args.duration, args.real_time_factor, os.cpu_count()))
    print('%4s %8s %10s %8s %8s %8s %s' % ('jobs', 'wall s', 'subs/hour', 'rtf min',
                                          'rtf med', 'same', 'verdicts'))
    first, detail = None, None
    for jobs in args.jobs:
        wall, report, summary = grade(folder, os.path.join(scratch, 'jobs%d' % jobs), jobs,
                                      args.duration, args.real_time_factor)
        verdicts = {s['name']: s['verdict'] for s in report['submissions']}
        first = first or verdicts
        factors = [r['real_time_factor'] for r in report['runs'] if r.get('real_time_factor')]
        print('%4d %8.0f %10.1f %8.2f %8.2f %8s %s' % (
            jobs, wall, count * 3600.0 / wall, min(factors), statistics.median(factors),
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


if __name__ == '__main__':
    main(sys.argv[1:])

"""``bash tools/run bench grade --dask K``: one Dask worker taking K runs
against two taking K/2 each, on this machine (bench/grade.py)."""
import os
import statistics
import subprocess
import sys
import time


def _row(label, wall, report, count):
    factors = [r['real_time_factor'] for r in report['runs'] if r.get('real_time_factor')]
    workers = {r['workers'][-1] for r in report['runs'] if r.get('workers')}
    print('%-22s %8.0f %10.1f %8.2f %8.2f %8d' % (label, wall, count * 3600.0 / wall,
                                                  min(factors), statistics.median(factors),
                                                  len(workers)))


def dask_rows(args, folder, scratch, count, grade):
    """The scaling row: one worker with K runs, then two with K/2 each
    (``grade``: bench/grade.py's, one grading)."""
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

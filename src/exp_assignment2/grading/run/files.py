"""What the grader reads of a run's files (no ROS): whether a package's
Python waits on the wall clock, the size of a run's directory, and its logs'
sizes at the end of the run."""
import os
import re

from exp_assignment2.grading.entry.reading import python_files

WALL_CLOCK = re.compile(r'\btime\.(sleep|time)\s*\(|\brospy\.Rate\b.*\bwall\b')


def waits_on_wall_clock(package_dir):
    """[(file, line)] where the package's Python waits on or reads the wall clock."""
    found = []
    for path in python_files(package_dir, skipped=('build', 'devel')):
        try:
            with open(path, errors='replace') as f:
                for number, line in enumerate(f, 1):
                    if WALL_CLOCK.search(line.split('#')[0]):
                        found.append((os.path.relpath(path, package_dir), number))
        except OSError:
            continue
    return found


def directory_size(path):
    total = 0
    for root, _dirs, files in os.walk(path):
        for name in files:
            try:
                total += os.lstat(os.path.join(root, name)).st_size
            except OSError:
                pass
    return total


def log_sizes(work):
    """{log path: size} now: what is read of the logs is what was written up to
    the end of the run (a node's last words at shutdown are not its crash)."""
    sizes = {}
    for root, _dirs, files in os.walk(work):
        if '/src' in root[len(work):][:4] or '/overlay' in root[len(work):][:8]:
            continue
        for name in files:
            if name.endswith('.log'):
                path = os.path.join(root, name)
                try:
                    sizes[os.path.relpath(path, work)] = os.path.getsize(path)
                except OSError:
                    pass
    return sizes

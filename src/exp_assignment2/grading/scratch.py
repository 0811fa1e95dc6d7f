"""The grader's scratch directories (no ROS): each named for the process that
made it (``exp2-grade-PID-...``: a run's on its worker; ``exp2-teacher-PID-...``:
the teacher's side's copies of the class), removed by that process at its end,
and, when it was killed (SIGKILL leaves it no time), by the next grader
process that makes one on the machine."""
import os
import re
import shutil
import tempfile

STALE = re.compile(r'^exp2-(grade|teacher)-(\d+)-[A-Za-z0-9_]+$')


def alive(pid):
    """Is process ``pid`` there (another user's counts)?"""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True
    return True


def remove_stale(root=None):
    """The scratch directories in ``root`` (the temporary directory) of grader
    processes that are gone, removed; [their names]."""
    root = root or tempfile.gettempdir()
    removed = []
    try:
        names = os.listdir(root)
    except OSError:
        return removed
    for name in names:
        match = STALE.match(name)
        if match and not alive(int(match.group(2))):
            shutil.rmtree(os.path.join(root, name), ignore_errors=True)
            removed.append(name)
    return removed


def make(kind, root=None):
    """A new scratch directory of this process's (``kind``: grade or teacher),
    after those of killed graders were removed."""
    remove_stale(root)
    return tempfile.mkdtemp(prefix='exp2-%s-%d-' % (kind, os.getpid()), dir=root)

"""pybullet, imported once with its start-up banner silenced.

pybullet writes "pybullet build time: ..." to the process's stderr from C
when it is imported; a ROS user's launch output should show none of the
physics engine's chatter, so the import runs with file descriptors 1 and 2
pointed at /dev/null (import errors still arrive, as Python exceptions).
"""
import os
import sys


def _quiet_import():
    sys.stdout.flush()
    sys.stderr.flush()
    devnull = os.open(os.devnull, os.O_WRONLY)
    saved = [os.dup(1), os.dup(2)]
    os.dup2(devnull, 1)
    os.dup2(devnull, 2)
    try:
        import pybullet
    finally:
        for fd, copy in zip((1, 2), saved):
            os.dup2(copy, fd)
            os.close(copy)
        os.close(devnull)
    return pybullet


p = _quiet_import()

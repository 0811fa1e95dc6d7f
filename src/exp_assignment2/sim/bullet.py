"""pybullet, imported once with its chatter silenced.

pybullet writes "pybullet build time: ..." to the process's stderr from C
when it is imported, and its EGL plugin prints its GL details when loaded
and unloaded; a ROS user's launch output should show none of the physics
engine's chatter. :func:`quiet` points file descriptors 1 and 2 at /dev/null
for such a call (errors still arrive, as Python exceptions).
"""
import contextlib
import os
import sys


@contextlib.contextmanager
def quiet():
    """Silence what C code writes to stdout and stderr inside the block."""
    sys.stdout.flush()
    sys.stderr.flush()
    devnull = os.open(os.devnull, os.O_WRONLY)
    saved = [os.dup(1), os.dup(2)]
    os.dup2(devnull, 1)
    os.dup2(devnull, 2)
    try:
        yield
    finally:
        for fd, copy in zip((1, 2), saved):
            os.dup2(copy, fd)
            os.close(copy)
        os.close(devnull)


with quiet():
    import pybullet as p  # noqa: E402  (imported here, silenced)

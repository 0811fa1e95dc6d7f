"""An exclusive lock on a file, for one build of an overlay at a time: another
shell (or grader) building the same overlay is waited for, at most a given
time (the main thread's SIGALRM)."""
import fcntl
import os
import signal


class Locked:
    """Hold ``path``'s lock inside a ``with``; ``waiting(text)`` says so when
    another holder makes it wait; TimeoutError after ``timeout`` s of waiting."""

    def __init__(self, path, timeout, waiting=None):
        self.path, self.timeout, self.waiting = path, int(timeout), waiting
        self.file = None

    def __enter__(self):
        os.makedirs(os.path.dirname(self.path), exist_ok=True)
        self.file = open(self.path, 'w')
        try:
            fcntl.flock(self.file, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            if self.waiting is not None:
                self.waiting('waiting for another build of this overlay (at most %d s)'
                             % self.timeout)
            before = signal.signal(signal.SIGALRM, self._timed_out)
            signal.alarm(self.timeout)
            try:
                fcntl.flock(self.file, fcntl.LOCK_EX)
            except TimeoutError:
                self.file.close()
                raise
            finally:
                signal.alarm(0)
                signal.signal(signal.SIGALRM, before)
        return self

    def __exit__(self, *exc):
        self.file.close()

    def _timed_out(self, _signum, _frame):
        raise TimeoutError('another build of this overlay held it for %d s' % self.timeout)

"""The teacher stopping a grading (no ROS): Ctrl-C once, no new run starts,
the running ones finish and are recorded, and the report is written; twice
(or SIGTERM), the running ones are stopped now, their sandboxes removed; a
third time, the grader leaves at once. The signal handlers only count: the
grading's loop (:func:`~exp_assignment2.grading.run.dispatch.grade`) looks
at :attr:`Stopping.asked` and says on the terminal what it does.
"""
import signal

NO_NEW, NOW = 1, 2      # what Stopping.asked means


class Stopping(object):
    """How far the teacher asked the grading to stop: 0, :data:`NO_NEW` or
    :data:`NOW`; SIGINT and SIGTERM counted while it is entered (``with``)."""

    def __init__(self):
        self.asked = 0
        self._previous = {}

    def _interrupt(self, *_):
        self.asked += 1
        if self.asked > NOW:        # a third time: out at once (the report of what ended)
            raise KeyboardInterrupt()

    def _terminate(self, *_):
        if self.asked >= NOW:
            raise KeyboardInterrupt()
        self.asked = NOW

    def __enter__(self):
        for number, handler in ((signal.SIGINT, self._interrupt),
                                (signal.SIGTERM, self._terminate)):
            self._previous[number] = signal.getsignal(number)
            signal.signal(number, handler)
        return self

    def __exit__(self, *exc):
        for number, handler in self._previous.items():
            signal.signal(number, handler)
        self._previous = {}

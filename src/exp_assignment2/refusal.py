"""Refusing bad input without flooding the log (no ROS).

:class:`RefusalLog` turns each refusal into one log line, but at most about
one line per ``period`` seconds per interface; the refusals in between are
counted and their number is logged with the next line, or on its own once
the burst is over. Reasons come from :mod:`exp_assignment2.grammar`, which
already quotes at most 80 characters of the input.
"""
import threading
import time

from exp_assignment2.grammar import CommandError

MAX_LINE = 2000     # no refusal line is longer than this


def _daemon_timer(delay, fn):
    timer = threading.Timer(delay, fn)
    timer.daemon = True
    timer.start()
    return timer


class RefusalLog(object):
    """Logs refusals on one interface, throttled, with a count of those held back.

    :param interface: what the input came in on, e.g. ``'/ball/command'``
    :param log: called with one line (e.g. ``rospy.logerr``)
    :param now: wall clock (s); throttling is about log volume, so wall time
    :param schedule: ``schedule(delay, fn)`` runs ``fn`` later (a daemon timer)
    :param what: the word for what happened to the input (refused, clamped)
    """

    def __init__(self, interface, log, period=1.0, now=time.monotonic,
                 schedule=_daemon_timer, what='refused'):
        self.interface, self.log, self.period, self.what = interface, log, period, what
        self.now, self.schedule = now, schedule
        self.lock = threading.Lock()
        self.last = None          # when the last line was written
        self.held = 0             # refusals since then, not yet logged
        self.flush_pending = False

    def __call__(self, reason):
        with self.lock:
            t = self.now()
            if self.last is not None and t - self.last < self.period:
                self.held += 1
                if not self.flush_pending:
                    self.flush_pending = True
                    self.schedule(self.period - (t - self.last), self.flush)
                return
            line = self._line(reason)
            self.last, self.held = t, 0
        self.log(line)

    def flush(self):
        """Log the count of refusals held back, if any (the timer calls it)."""
        with self.lock:
            self.flush_pending = False
            if not self.held:
                return
            line = '%s: %d more %s in the last %.0f s' % (self.interface, self.held, self.what,
                                                          self.period)
            self.last, self.held = self.now(), 0
        self.log(line)

    def _line(self, reason):
        line = '%s: %s' % (self.interface, reason)
        if self.held:
            line += ' (and %d more %s)' % (self.held, self.what)
        return line[:MAX_LINE]


def parse_or_refuse(parser, text, refuse):
    """``parser(text)``, or None after ``refuse(reason)`` when it raises
    :class:`~exp_assignment2.grammar.CommandError`."""
    try:
        return parser(text)
    except CommandError as exc:
        refuse(str(exc))
        return None

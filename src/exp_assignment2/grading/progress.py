"""The grading's progress on the terminal (no ROS): done, running, left and
the time to go, on one line rewritten in place on a terminal, or a line
every half minute when the output is a file."""
import sys
import time


class Progress(object):
    def __init__(self, total, jobs, stream=None, extra=None):
        self.total, self.jobs = total, jobs
        self.stream = stream or sys.stderr
        self.tty = hasattr(self.stream, 'isatty') and self.stream.isatty()
        self.started = time.monotonic()
        self.last_line, self.last_text = 0.0, ''
        self.extra = extra          # fn() -> text added to the line (e.g. Dask's workers)

    def text(self, runs):
        done = sum(r.state == 'done' for r in runs)
        running = sum(r.state in ('building', 'running', 'ending') for r in runs)
        left = self.total - done - running
        elapsed = time.monotonic() - self.started
        eta = ''
        if done:
            eta = ', about %s to go' % _clock(elapsed / done * (self.total - done))
        width = 24
        filled = int(width * done / max(1, self.total))
        extra = (', ' + self.extra()) if self.extra else ''
        return '[%s%s] %d done, %d running, %d left, %s%s%s' % (
            '#' * filled, '.' * (width - filled), done, running, left, _clock(elapsed), eta,
            extra)

    def show(self, runs):
        text = self.text(runs)
        now = time.monotonic()
        if self.tty:
            self.stream.write('\r' + text.ljust(len(self.last_text)))
            self.stream.flush()
        elif text.split(',')[0] != self.last_text.split(',')[0] or now - self.last_line > 30:
            self.stream.write(text + '\n')
            self.stream.flush()
            self.last_line = now
        self.last_text = text

    def line(self, text):
        if self.tty:
            self.stream.write('\n')
        self.stream.write(text + '\n')
        self.stream.flush()

    def close(self):
        if self.tty and self.last_text:
            self.stream.write('\n')
            self.stream.flush()


def _clock(seconds):
    seconds = int(seconds)
    return '%d:%02d' % (seconds // 60, seconds % 60) if seconds < 3600 else \
        '%d:%02d:%02d' % (seconds // 3600, seconds // 60 % 60, seconds % 60)

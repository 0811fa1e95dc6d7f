"""Keeping simulated time in step with the wall clock, and with the
consumers of the camera (no ROS, no pybullet)."""
import collections
import threading
import time

# real_time_factor 0's ceiling: ROS nodes in other processes close their loops
# (odometry in, a velocity command out) in a few ms of wall time; at 20x that is
# a tenth of a simulated second, the most a 0.5 s command timeout and the
# controllers' gains can take. Unbounded, a world without a camera runs at
# 45-100x on 2 cores and its nodes' control diverges.
MAX_REAL_TIME_FACTOR = 20.0


class Pacer(object):
    """Holds simulated time to ``real_time_factor`` x wall time.

    After each physics step the loop asks :meth:`delay` how long to wait.
    ``real_time_factor`` 0 means as fast as possible, up to
    ``max_real_time_factor`` (0: no ceiling). A loop that falls more than
    ``max_lag`` s of simulated time behind (a slow frame, a pause) starts again
    from where it is instead of racing to catch up. A loop less than
    ``min_ahead`` simulated s ahead steps on without waiting (2 ms: a wait
    every other 1 ms step, at any factor): at 1 kHz and real time a wait after
    every step cost 0.029 of a core in waiting alone, after every other 0.016;
    simulated time is never more than ``min_ahead`` and a step ahead.
    """

    def __init__(self, real_time_factor, wall=time.monotonic, max_lag=0.25,
                 max_real_time_factor=MAX_REAL_TIME_FACTOR, min_ahead=0.002):
        for name, value in (('real_time_factor', real_time_factor),
                            ('max_real_time_factor', max_real_time_factor)):
            if not (value >= 0.0 and value != float('inf')):
                raise ValueError('%s must be >= 0 (0: as fast as possible), got %r'
                                 % (name, value))
        self.rtf, self.wall, self.max_lag = float(real_time_factor), wall, max_lag
        self.min_ahead = float(min_ahead)
        self.pace = self.rtf or float(max_real_time_factor)     # 0: no pace at all
        self.wall0 = self.sim0 = None

    def restart(self, sim_time):
        """Count from here (at start and after a pause)."""
        self.wall0, self.sim0 = self.wall(), sim_time

    def delay(self, sim_time):
        """Wall seconds to wait so that ``sim_time`` is not ahead of the wall."""
        if self.pace == 0.0:
            return 0.0
        if self.wall0 is None:
            self.restart(sim_time)
        due = self.sim0 + (self.wall() - self.wall0) * self.pace
        ahead = sim_time - due
        if ahead < -self.max_lag:
            self.restart(sim_time)
            return 0.0
        return ahead / self.pace if ahead >= self.min_ahead else 0.0


class FramePace(object):
    """At real_time_factor 0, holds a camera's frames for the consumers that
    acknowledge them, so that every frame reaches them.

    As fast as possible is as fast as the slowest of them: a consumer that
    falls behind would otherwise lose frames from its queue (the state
    machine keeps 3), and the world it steers in runs on without it. A
    consumer acknowledges a frame by its stamp (:meth:`done`; stamp 0, before
    any frame, announces it, so that its first frames wait too); before a new
    frame, :meth:`wait` holds the simulation while a consumer still has
    ``window`` frames unacknowledged. Consumers that acknowledge nothing are
    not waited for. One that a wait has held for ``patience`` wall seconds
    with no acknowledgement (dead, being restarted, stopped in a debugger) is
    not waited for until it acknowledges again, and ``log`` says so once; a
    consumer that joins (or comes back) is counted from the newest frame
    sent, so that it is not behind at once. An acknowledgement of a frame
    newer than any sent since the last :meth:`reset` (one still on its way
    when time went back, or a latched one replayed to a new simulator) is
    ignored.

    :param log: the host's logger (``info``), or None
    :param now: wall clock (s)
    """

    def __init__(self, window=3, patience=1.0, log=None, now=time.monotonic):
        self.window, self.patience, self.now, self.log = window, patience, now, log
        self.cond = threading.Condition()
        self.sent = collections.deque()     # stamps (ns) of frames handed over, oldest first
        self.newest = -1                    # the newest stamp sent since the last reset
        self.consumers = {}                 # name -> [last stamp done (ns), wall time, waited for]

    def done(self, consumer, stamp_ns):
        """``consumer`` has finished with the frame stamped ``stamp_ns``."""
        with self.cond:
            if stamp_ns > max(self.newest, 0):
                return                      # a frame from before the last reset
            stamp_ns = stamp_ns or -1       # 0: none yet (a frame stamped 0 counts as unseen)
            entry = self.consumers.get(consumer)
            if entry is None or not entry[2]:
                stamp_ns = max(stamp_ns, self.newest)
                if self.log is not None:
                    self.log.info('camera: %s acknowledges frames: the simulation waits for it'
                                  % consumer)
            self.consumers[consumer] = [stamp_ns, self.now(), True]
            self.cond.notify_all()

    def _behind(self):
        """The consumers waited for that have ``window`` frames unacknowledged."""
        late = []
        for name, (stamp, _, waited) in self.consumers.items():
            if waited and sum(1 for s in self.sent if s > stamp) >= self.window:
                late.append(name)
        return late

    def wait(self):
        """Before a frame: wait while a consumer is ``window`` frames behind."""
        with self.cond:
            started = self.now()
            while True:
                late = self._behind()
                if not late:
                    return
                now = self.now()
                let_go = False
                for name in late:
                    entry = self.consumers[name]
                    held = now - max(entry[1], started)
                    if held >= self.patience:
                        entry[2], let_go = False, True
                        if self.log is not None:
                            self.log.info('camera: %s acknowledged no frame for %.1f s: not '
                                          'waiting for it' % (name, held))
                if not let_go:
                    self.cond.wait(min(0.1, self.patience))

    def sent_frame(self, stamp_ns):
        """A frame stamped ``stamp_ns`` is handed over."""
        with self.cond:
            self.sent.append(stamp_ns)
            self.newest = stamp_ns
            oldest = min((c[0] for c in self.consumers.values() if c[2]), default=stamp_ns)
            while len(self.sent) > self.window and self.sent[0] <= oldest:
                self.sent.popleft()

    def reset(self):
        """Time went back (reset_simulation): forget the stamps."""
        with self.cond:
            self.sent.clear()
            self.newest = -1
            for entry in self.consumers.values():
                entry[0] = -1
            self.cond.notify_all()

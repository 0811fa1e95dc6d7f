"""How many runs at once, from what runs cost on this machine (no ROS, no Dask).

A fixed ``--jobs`` from a figure measured once on one submission starved the
runs of a class that cost more (a run below 0.95 of its real-time factor is
judged while its code ran slower than it was written for). Here a run starts
only when the cores it will need are free, each counted at what its own
submission's code costs: the submission's runs measured so far (its releases,
repeats and episodes run the same code), else the class's median of the runs
that finished, else the profile's ``cpu_per_run`` (their CPU s per simulated
s, from their control group: the record's ``cpu_s`` and ``sim_time``), at the
real-time factor it is run at; a submission not yet measured whose Python has a
loop that can go round without waiting (plan.busy_loops) is counted
:data:`BUSY` cores dearer than the median or the profile's figure, whichever is
more, as such a loop keeps a core busy (a real class's cheap runs, whose camera
nobody watched, pulled the median to 0.36 and started a run of 1.31 cores
beside one of 0.71: it starved). A submission not yet measured whose robot
files say what its camera draws (plan.camera_load) is counted at the runs of a
camera alike, else at the class's costs scaled to its camera
(:func:`camera_load`): the course's 800 x 800 at 30 Hz costs four times this
package's 320 x 240 at 15 Hz. The queue is taken in order, each run that
fits the free cores (but :data:`TEACHER`, the grading's own) started (first
fit: a cheap run starts beside a dear one where the next in line would not
fit); ``--jobs`` is only the most at once. The first run always starts,
whatever it is expected to cost.

A running run's cost is read as it runs (cpu.Pace: from its 20th simulated s,
every 10 wall s, counted :data:`LIVE_MARGIN` dearer) and counts at once, for it
and for what is not yet measured: a second run starts beside the first within
a minute of its start, not when the first has ended, and a submission thought
dear (a busy loop) that is not is counted at what it costs. A run whose
commands are asked to end counts :data:`ENDING` cores from then on: the next
one starts as it ends. A resumed grading counts the costs of the runs it keeps
from the start.

A run that was starved all the same (the machine was busier than measured: a
submission that costs more than the others, another program) is run again
once the others are done, alone, and its page says why; a first attempt seen to
fall behind is ended as soon as it is (run.ending's ``starved``: a window of 30
wall s under 0.85 of its factor), not at its end, so that little of the
machine's time goes to a run that will not count
(:data:`STARVED_NOTE`). On a Dask scheduler's workers (``cores`` None) each
worker's ``runs`` resource is the limit, and the starved runs are run again
after the others there too.
"""
import math

STARVED = 0.95            # of the factor asked: below it, a run was starved
MIN_SIM = 10.0            # simulated s a run must have lasted for its cost to count
QUANTILE = 0.5            # an unmeasured submission's run counted at the class's median
BUSY = 0.8                # cores more for one whose Python loops without waiting (a real
                          # class: 0.9 to 1.2 cores of student code, the others 0.1 to 0.5)
FIXED = 0.25              # of a run's cost, the part no camera frame makes (the simulator's
                          # step, ROS, the display): a real class's runs with no frame drawn
                          # cost 0.22 to 0.24 of a core against 0.62 to 0.66 at 30 frames a
                          # second (0.35); the bench's mixed class, 0.12 to 0.18 at 1.8 (0.2)
ALIKE = 1.5               # cameras whose frames a second are within this factor: alike
REFERENCE_FRAMES = 30.0   # frames of 800 x 800 a second the profiles' cpu_per_run was measured
                          # at (the course's camera: 800 x 800 at 30 Hz)
LIVE_MARGIN = 1.1         # a running run's pace counted this much dearer: its start-up is
                          # not in it, and a dog that slept so far may play from now on
TEACHER = 0.1             # cores the grading's own process keeps busy beside the runs (Dask,
                          # each run's monitor and ground truth): 26 CPU s of a 383 s grading
ENDING = 0.1              # cores an ending run is counted at: its nodes stopping, its
                          # record packed (a real class: 1 to 16 wall s of a run's 250)
STARVED_NOTE = 'run again: its first run was starved (%.2f of real time)'


def starved(result):
    """The factor a finished run achieved when it fell below STARVED of the
    one asked (a run that reached its simulation), or the one it kept when it was
    ended for falling behind (run.ending's ``starved``), else None."""
    result = result or {}
    if result.get('ended_by') == 'starved':
        return result.get('starved_factor') or result.get('real_time_factor') or 0.0
    achieved, asked = result.get('real_time_factor'), result.get('real_time_factor_asked')
    if not achieved or not asked or not (result.get('truth') or {}).get('sim_time'):
        return None
    return achieved if achieved < STARVED * asked else None


def camera_load(frames):
    """A run's cost at ``frames`` of 800 x 800 a second (plan.camera_load), as a
    share of its cost at REFERENCE_FRAMES: FIXED, and the rest in proportion."""
    return FIXED + (1.0 - FIXED) * frames / REFERENCE_FRAMES


def _median(values):
    values = sorted(values)
    return values[int(round(QUANTILE * (len(values) - 1)))]


def cost(result):
    """Cores a finished run kept busy per unit of real-time factor (CPU s
    per simulated s), or None when it did not run long enough to say."""
    result = result or {}
    cpu, sim = result.get('cpu_s') or {}, (result.get('truth') or {}).get('sim_time') or 0.0
    if not cpu or sim < MIN_SIM:
        return None
    return sum(cpu.values()) / sim


class Admission(object):
    """Which runs may start now (see the module docstring).

    :param cores: the cores runs may use (None: no limit, a Dask scheduler's)
    :param first: the profile's ``cpu_per_run``, the estimate until a run is measured
    :param most: the most runs at once (``--jobs``)
    """

    def __init__(self, cores, first, most):
        self.cores, self.first, self.most = cores, float(first), max(1, int(most))
        self.costs = []             # measured, CPU s per simulated s
        self.mine = {}              # submission -> its runs' measured costs
        self.running = {}           # label -> cores counted for it
        self.asked = {}             # label -> (its submission, the factor it runs at)
        self.paces = {}             # label -> its pace as it runs (CPU s per simulated s)
        self.busy = set()           # submissions whose Python loops without waiting
        self.frames = {}            # submission -> its camera's frames of 800 x 800 a second
        self.measured = []          # (submission, cost) of every finished run counted

    def expect_busy(self, name):
        """Submission ``name`` has a loop that can go round without waiting: until
        its own run is measured, it is counted BUSY cores dearer."""
        self.busy.add(name)

    def expect_frames(self, name, frames):
        """Submission ``name``'s robot files declare cameras of ``frames`` of 800 x 800
        a second at most (plan.camera_load): until its own run is measured, it is
        counted at the median of the runs of a camera alike (within ALIKE), else of
        the class's costs scaled to its camera (camera_load), else at the profile's
        figure scaled."""
        if isinstance(frames, (int, float)) and math.isfinite(frames) and frames >= 0:
            self.frames[name] = float(frames)

    def per_run(self, name=None):
        """CPU s per simulated s counted for a run of submission ``name``: what its own
        runs measured (the most of them: its releases, repeats and episodes run the same
        code), else the class's median, else the profile's figure (BUSY more for a
        submission that loops without waiting, on the median or the profile's figure,
        whichever is more)."""
        if name is not None and self.mine.get(name):
            return max(self.mine[name])
        running = [pace for label, pace in self.paces.items()
                   if self.asked.get(label, (None,))[0] == name]
        if name is not None and running:
            return max(running)
        known = self.costs + list(self.paces.values())
        median = _median(known) if known else self.first
        first = self.first
        frames = self.frames.get(name)
        if frames is not None:
            # the runs of a camera alike, else the class's costs each scaled from its camera
            # to this one, else the profile's figure scaled
            load, framed = camera_load(frames), self._framed()
            alike = [c for c, f in framed if min(f, frames) * ALIKE >= max(f, frames)]
            median = _median(alike) if alike else \
                _median([c * load / camera_load(f) for c, f in framed]) if framed else \
                first * load / camera_load(REFERENCE_FRAMES)
            first *= load / camera_load(REFERENCE_FRAMES)
        if name in self.busy:       # one that spins watches its camera and works: never
            return max(median, first) + BUSY    # the median of runs that hardly ran
        return median

    def _framed(self):
        """(cost, its camera's frames a second) of the measured and running runs whose
        submission's camera is known."""
        framed = [(c, self.frames[n]) for n, c in self.measured if n in self.frames]
        return framed + [(pace, self.frames[self.asked[label][0]])
                         for label, pace in self.paces.items()
                         if self.asked.get(label, (None,))[0] in self.frames]

    def need(self, rtf, name=None):
        """Cores a run at real-time factor ``rtf`` is counted at (0, as fast
        as possible: every core)."""
        if self.cores is None:
            return 0.0
        if not rtf:
            return float(self.cores)
        return self.per_run(name) * rtf

    def may_start(self, rtf, name=None):
        """May a run of ``name`` at factor ``rtf`` start now (with what runs)?"""
        if not self.running:
            return True
        if len(self.running) >= self.most:
            return False
        return self.cores is None or sum(self.running.values()) + self.need(rtf, name) <= \
            self.cores - TEACHER + 1e-9

    def started(self, label, rtf, name=None):
        self.running[label] = self.need(rtf, name)
        self.asked[label] = (name, rtf)

    def pace(self, label, pace):
        """Running run ``label`` costs ``pace`` CPU s per simulated s as it runs
        (cpu.Pace): counted at it from now on (LIVE_MARGIN dearer), and for the
        runs not yet measured."""
        if label not in self.running or not isinstance(pace, (int, float)) or \
                not math.isfinite(pace) or pace < 0:
            return
        rtf = self.asked[label][1]
        self.paces[label] = pace * LIVE_MARGIN
        if self.cores is not None and rtf:
            self.running[label] = self.paces[label] * rtf

    def ending(self, label):
        """Running run ``label`` is ending (its commands asked to end, its record
        being packed): it is counted at :data:`ENDING` cores from now on, so that the
        next run builds and starts as it ends; its cost is counted when it is back."""
        if label in self.running:
            self.running[label] = min(self.running[label], ENDING)
            self.paces.pop(label, None)

    def counted(self, result, name=None):
        """A finished run's cost counted (one kept by a resumed grading too)."""
        measured = cost(result)
        if measured is not None:
            self.costs.append(measured)
            self.measured.append((name, measured))
            if name is not None:
                self.mine.setdefault(name, []).append(measured)

    def ended(self, label, result, name=None):
        """A run came back: its cost counted. True when it is to be run again
        (starved, the first time)."""
        self.running.pop(label, None)
        self.asked.pop(label, None)
        self.paces.pop(label, None)
        self.counted(result, name)
        return starved(result) is not None

    def most_at_once(self, rtf=1.0):
        """How many runs at ``rtf`` the estimate lets run at once now."""
        if self.cores is None:
            return self.most
        need = self.need(rtf)
        return max(1, min(self.most, int((self.cores - TEACHER) / need + 1e-9) if need
                                    else self.most))

"""The person MiRo plays with: what they say and where they are (no ROS).

:class:`Ears` keeps what was said: a word is valid for ``voice_timeout`` s and
only in the state it was said in (entering a state forgets the rest; a word
still valid then, said as the state ended, gets a line saying it came too
late). While MiRo is busy moving in PLAY (:meth:`Ears.busy` to
:meth:`Ears.ready`), words wait without ageing, so an order is never lost to
a long drive. Asleep, MiRo does not listen: one line says so.

:class:`Person` knows where the person is and points: the last gesture, else
the configured place. :class:`SimulatedPerson` stands in, from a seeded
generator, when nobody talks (as the original's random user did).
"""
import threading

from exp_assignment2 import grid
from exp_assignment2.grammar import format_go_to

CALL = ('play',)          # VoiceCommand kinds: 'play' (also 'hey buddy') and 'go_to'
ORDER = ('go_to',)


class Ears(object):
    """Words heard, per state, with their validity."""

    def __init__(self, clock, log, voice_timeout=10.0):
        self.clock, self.log, self.voice_timeout = clock, log, voice_timeout
        self.lock = threading.Lock()
        self.state, self.words = None, []       # words: [(valid_from, VoiceCommand, text)]
        self.told_asleep = False
        self.busy_since = None                  # set while MiRo moves in PLAY

    def enter(self, state):
        """MiRo enters ``state``: what was said before no longer counts."""
        with self.lock:
            late = [text for _, _, text in self._fresh()]
            left = self.state
            self.state, self.words, self.told_asleep = state, [], False
            self.busy_since = None
        for text in late:
            self.log.info('%s is over: %r came too late; not kept', left, text)

    def hear(self, cmd, text=''):
        """A word arrives (any thread)."""
        with self.lock:
            state = self.state
            if state == 'SLEEP':
                if not self.told_asleep:
                    self.told_asleep = True
                    self.log.info('SLEEP: MiRo is asleep and does not listen (%r not heard)',
                                  text or cmd.kind)
                return
            if state == 'NORMAL' and cmd.kind not in CALL:
                self.log.info('NORMAL: %r only counts in PLAY; not kept', text or cmd.kind)
                return
            self.words.append((self.clock.now(), cmd, text or _text_of(cmd)))
        self.clock.notify()

    def busy(self):
        """MiRo starts moving: what is said now waits, without ageing."""
        with self.lock:
            self.busy_since = self.clock.now()

    def ready(self):
        """MiRo is free again: waiting words age from now on."""
        now = self.clock.now()
        with self.lock:
            since, self.busy_since = self.busy_since, None
            if since is not None:
                self.words = [(t + now - since if t < since else now, cmd, text)
                              for t, cmd, text in self.words]

    def _fresh(self):
        now = self.clock.now() if self.busy_since is None else self.busy_since
        self.words = [w for w in self.words if now - w[0] <= self.voice_timeout]
        return self.words

    def has(self, kinds):
        with self.lock:
            return any(c.kind in kinds for _, c, _ in self._fresh())

    def take(self, kinds):
        """The oldest valid word of ``kinds`` (removed), or None."""
        with self.lock:
            for item in self._fresh():
                if item[1].kind in kinds:
                    self.words.remove(item)
                    return item[1]
        return None


def _text_of(cmd):
    return format_go_to(cmd.x, cmd.y) if cmd.kind == 'go_to' else cmd.kind


class SimulatedPerson(object):
    """Random words and gestures from a seeded generator."""

    def __init__(self, rng, call_probability=0.3):
        self.rng, self.call_probability = rng, call_probability

    def point(self):
        return (self.rng.randint(grid.GRID_MIN, grid.GRID_MAX),
                self.rng.randint(grid.GRID_MIN, grid.GRID_MAX))

    def says(self, playing):
        """Text the person says, or '' for silence."""
        if not playing:
            if self.rng.random() < self.call_probability:
                return self.rng.choice(['play', 'hey buddy'])
            return ''
        choice = self.rng.randrange(3)
        if choice == 0:
            return 'go to %d %d' % self.point()
        if choice == 1:
            return self.rng.choice(['play', 'hey buddy'])
        return ''

    def gesture(self):
        """((person_x, person_y), (point_x, point_y))."""
        return self.point(), self.point()


class Person(object):
    """Where the person is and where they point."""

    def __init__(self, default=grid.PERSON, simulated=None, on_move=None):
        self.default, self.simulated = tuple(default), simulated
        self.lock = threading.Lock()
        self.gesture = None          # ((px, py), (gx, gy)), the last real one
        self.on_move, self.place = on_move, tuple(default)   # told where the person stands

    def saw_gesture(self, person, point):
        """A real gesture arrived (any thread)."""
        with self.lock:
            self.gesture = (tuple(person), tuple(point))
        self._moved(tuple(person))

    def _moved(self, place):
        if place != self.place:
            self.place = place
            if self.on_move is not None:
                self.on_move(place)

    def pointing(self, fallback=None):
        """Where the last real gesture points, else ``fallback``."""
        with self.lock:
            return self.gesture[1] if self.gesture is not None else fallback

    def look(self):
        """((px, py), (gx, gy) or None): the last real gesture; else a simulated
        one; else the configured place, pointing nowhere."""
        with self.lock:
            if self.gesture is not None:
                return self.gesture
        if self.simulated is not None:
            seen = self.simulated.gesture()
            self._moved(tuple(seen[0]))
            return seen
        return self.default, None

"""Scenario B's behaviour: MiRo's SMACH states SLEEP (initial), NORMAL, PLAY.

Written against a clock, a :class:`~.interfaces.MiroBody`, :class:`.person.Ears`
and :class:`.person.Person`. Awake, MiRo listens all the time: a call word at
any moment of NORMAL, also mid-wander, starts PLAY at once (the wander is
abandoned: PLAY's first order retargets the motion controller).
"""
import math

from exp_assignment2.grammar import format_go_to, parse_voice
from exp_assignment2.behaviour.person import CALL, ORDER
from exp_assignment2.smach_api import smach

# SMACH label -> the original's /state parameter value
STATE_PARAM = {'SLEEP': 'SLEEP STATE', 'NORMAL': 'NORMAL', 'PLAY': 'PLAY STATE'}


class MiroParams(object):
    """The behaviour's numbers: ``get(name, default)`` for each."""

    DEFAULTS = dict(loops=3, sleep_probability=0.2, sleep_time=4.0, listen_time=3.0,
                    arrival_timeout=60.0, wait_time=2.0, voice_timeout=10.0)

    def __init__(self, get=lambda name, default: default):
        for key, default in self.DEFAULTS.items():
            value = type(default)(get(key, default))
            if not math.isfinite(value) or value < 0:
                raise ValueError('%s must be a finite number >= 0, got %r' % (key, value))
            setattr(self, key, value)


class Miro(object):
    """What the states share."""

    def __init__(self, clock, body, ears, person, params, rng, log, simulated=None):
        self.clock, self.body, self.ears, self.person = clock, body, ears, person
        self.p, self.rng, self.log, self.simulated = params, rng, log, simulated

    def go(self, command, interrupt=()):
        """Order ``command`` and wait for the arrival, or for a word of
        ``interrupt`` kinds. 'arrived', 'interrupted', 'failed' or 'shutdown'."""
        goal = self.body.go(command)
        self.clock.wait_until(lambda: goal.done() or self.ears.has(interrupt),
                              self.p.arrival_timeout)
        if self.clock.is_shutdown():
            return 'shutdown'
        if goal.succeeded():
            return 'arrived'
        if self.ears.has(interrupt):
            return 'interrupted'
        self.log.warn('%r: no arrival within %.0f s', command, self.p.arrival_timeout)
        return 'failed'

    def listen(self, kinds, playing):
        """A word of ``kinds`` said (and still valid) or said within
        ``listen_time``; else, with a simulated person, what they say."""
        if self.clock.wait_until(lambda: self.ears.has(kinds), self.p.listen_time):
            return self.ears.take(kinds)
        if self.simulated is not None and not self.clock.is_shutdown():
            text = self.simulated.says(playing)
            if text:
                self.log.info('the simulated person says %r', text)
                cmd = parse_voice(text)
                if cmd.kind in kinds:
                    return cmd
        return None


class MiroSleep(smach.State):
    """Go home, rest ``sleep_time``, then NORMAL; deaf meanwhile."""

    def __init__(self, miro):
        smach.State.__init__(self, outcomes=['wake', 'shutdown'])
        self.miro = miro

    def execute(self, ud):
        miro = self.miro
        miro.ears.enter('SLEEP')
        if miro.go('go_home') == 'shutdown':
            return 'shutdown'
        return 'wake' if miro.clock.sleep(miro.p.sleep_time) else 'shutdown'


class MiroNormal(smach.State):
    """Wander to random points, listening all along: a call word -> PLAY; by
    chance, or after ``loops`` wanders -> SLEEP."""

    def __init__(self, miro):
        smach.State.__init__(self, outcomes=['play', 'sleep', 'shutdown'])
        self.miro = miro

    def execute(self, ud):
        miro, p = self.miro, self.miro.p
        miro.ears.enter('NORMAL')
        for _ in range(p.loops):
            outcome = miro.go('go_rand', interrupt=CALL)
            if outcome == 'shutdown':
                return 'shutdown'
            if outcome == 'interrupted':
                miro.ears.take(CALL)
                miro.log.info('NORMAL: called while wandering; the wander is abandoned')
                return 'play'
            if miro.listen(CALL, playing=False) is not None:
                return 'play'
            if miro.clock.is_shutdown():
                return 'shutdown'
            if miro.rng.random() < p.sleep_probability:
                return 'sleep'
        return 'sleep'


class MiroPlay(smach.State):
    """Go to the person, then obey their ``go to X Y``, wait on a repeated
    call, or go where they point; ``loops`` orders, then NORMAL. An order
    said while MiRo moves is obeyed next."""

    def __init__(self, miro):
        smach.State.__init__(self, outcomes=['normal', 'shutdown'])
        self.miro = miro

    def execute(self, ud):
        miro, p = self.miro, self.miro.p
        miro.ears.enter('PLAY')
        done = 0
        while done < p.loops:
            (px, py), point = miro.person.look()
            if self._go(format_go_to(px, py)) == 'shutdown':
                return 'shutdown'
            cmd = miro.listen(CALL + ORDER, playing=True)
            if miro.clock.is_shutdown():
                return 'shutdown'
            done += 1
            if cmd is not None and cmd.kind == 'play':
                miro.log.info('PLAY: called again; waiting')
                miro.clock.sleep(p.wait_time)
                continue
            if cmd is None:                    # a gesture made on the way counts
                point = miro.person.pointing(point)
            target = (cmd.x, cmd.y) if cmd is not None else point
            if target is None:
                miro.log.info('PLAY: the person says nothing and points nowhere; waiting')
                continue
            if cmd is None:
                miro.log.info('PLAY: the person points at (%d, %d)', *target)
            if self._go(format_go_to(*target)) == 'shutdown':
                return 'shutdown'
            while done < p.loops and miro.ears.has(ORDER):    # said on the way: next
                order = miro.ears.take(ORDER)
                done += 1
                if self._go(format_go_to(order.x, order.y)) == 'shutdown':
                    return 'shutdown'
        return 'normal'

    def _go(self, command):
        self.miro.ears.busy()
        outcome = self.miro.go(command)
        self.miro.ears.ready()
        return outcome


def build_state_machine(miro):
    """SLEEP (initial) -> NORMAL <-> PLAY, NORMAL -> SLEEP."""
    sm = smach.StateMachine(outcomes=['shutdown'])
    with sm:
        smach.StateMachine.add('SLEEP', MiroSleep(miro), transitions={'wake': 'NORMAL'})
        smach.StateMachine.add('NORMAL', MiroNormal(miro),
                               transitions={'play': 'PLAY', 'sleep': 'SLEEP'})
        smach.StateMachine.add('PLAY', MiroPlay(miro), transitions={'normal': 'NORMAL'})
    return sm


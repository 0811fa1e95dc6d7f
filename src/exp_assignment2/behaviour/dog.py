"""Scenario A's behaviour: the dog's SMACH states NORMAL, SLEEP and PLAY.

Written against :mod:`.interfaces`: a clock, a :class:`~.interfaces.DogBody`
and :class:`~.interfaces.DogEyes`. Every duration is the clock's time (ROS
time in the running system, so it scales with the simulator) and every number
a parameter (:class:`DogParams`). Nothing polls: the states wait for an
event (a frame, a goal ending) or a deadline.
"""
import math

from exp_assignment2 import arena
from exp_assignment2.control import BallFollower
from exp_assignment2.smach_api import smach


class DogParams(object):
    """The behaviour's numbers: ``get(name, default)`` for each (e.g. a ROS
    private parameter reader); the defaults below."""

    DEFAULTS = dict(
        sleep_probability=0.2,      # NORMAL: chance of going to sleep each round
        look_around_time=6.0,       # NORMAL: s turning in place before wandering
        look_rate=0.5,              # rad/s while looking around or searching
        wander_timeout=60.0,        # NORMAL: s for one random goal
        home_timeout=120.0,         # SLEEP: s to reach the kennel
        sleep_time=14.0,            # SLEEP: s asleep at home
        lost_timeout=None,          # PLAY: s without the ball; default one full turn
        rest_speed=0.05,            # PLAY: |v|, |w| below this is "at rest"
        rest_time=1.0,              # PLAY: s at rest before the head sweep
        head_angle=math.radians(45),
        head_hold=2.0,              # PLAY: s holding each head position
        target_radius_ratio=0.3,    # PLAY: apparent ball radius / image width to keep
        max_linear=0.8,             # PLAY: servo limits
        max_angular=1.0,
    )

    def __init__(self, get=lambda name, default: default):
        for key, default in self.DEFAULTS.items():
            value = get(key, default)
            if value is not None:
                value = float(value)
                if not math.isfinite(value) or value < 0:
                    raise ValueError('%s must be a finite number >= 0, got %r' % (key, value))
            setattr(self, key, value)
        if self.lost_timeout is None:
            self.lost_timeout = 2.0 * math.pi / self.look_rate if self.look_rate else 12.6

    def follower(self):
        return BallFollower(self.target_radius_ratio, self.max_linear, self.max_angular,
                            search_rate=self.look_rate)


class Dog(object):
    """What the states share."""

    def __init__(self, clock, body, eyes, params, rng, log):
        self.clock, self.body, self.eyes, self.p = clock, body, eyes, params
        self.rng, self.log = rng, log

    def seen_since(self, t):
        seen = self.eyes.last_seen()
        return seen is not None and seen >= t


class Normal(smach.State):
    """Sleep by chance, else search: look around, then wander to a random
    point; the ball seen at any moment -> PLAY (the robot goal is cancelled)."""

    def __init__(self, dog):
        smach.State.__init__(self, outcomes=['sleep', 'play', 'shutdown'])
        self.dog = dog

    def execute(self, ud):
        dog, p, clock = self.dog, self.dog.p, self.dog.clock
        since = clock.now()

        def seen():
            return dog.seen_since(since)
        while not clock.is_shutdown():
            if dog.rng.random() < p.sleep_probability:
                return 'sleep'
            dog.body.drive(0.0, p.look_rate)
            found = clock.wait_until(seen, p.look_around_time)
            dog.body.stop()
            if found:
                return 'play'
            x, y = arena.random_point(dog.rng)
            dog.log.info('NORMAL: nothing seen, wandering to (%.1f, %.1f)', x, y)
            goal = dog.body.go_to(x, y)
            clock.wait_until(lambda: goal.done() or seen(), p.wander_timeout)
            if clock.is_shutdown():
                goal.cancel()
                break
            if seen():
                goal.cancel()
                dog.body.stop()
                dog.log.info('NORMAL: ball seen, robot goal preempted')
                return 'play'
            if not goal.succeeded():
                goal.cancel()
                dog.log.warn('NORMAL: (%.1f, %.1f) not reached; looking around again', x, y)
        return 'shutdown'


class Sleep(smach.State):
    """Go to the kennel, rest ``sleep_time``, wake up; the ball is ignored."""

    def __init__(self, dog):
        smach.State.__init__(self, outcomes=['wake', 'shutdown'])
        self.dog = dog

    def execute(self, ud):
        dog, p, clock = self.dog, self.dog.p, self.dog.clock
        goal = dog.body.go_to(*arena.KENNEL)
        clock.wait_until(goal.done, p.home_timeout)
        if clock.is_shutdown():
            goal.cancel()
            return 'shutdown'
        if not goal.succeeded():
            goal.cancel()
            dog.log.warn('SLEEP: the kennel was not reached; sleeping here')
        dog.body.stop()
        dog.log.info('SLEEP: resting %g s', p.sleep_time)
        return 'wake' if clock.sleep(p.sleep_time) else 'shutdown'


class Play(smach.State):
    """Follow the ball with the visual servo; at rest near it, sweep the head
    (+angle, hold, -angle, hold, 0); the ball unseen ``lost_timeout`` -> NORMAL."""

    def __init__(self, dog):
        smach.State.__init__(self, outcomes=['lost', 'shutdown'])
        self.dog = dog
        self.follower = dog.p.follower()
        self.frames, self.rest_since, self.entered = 0, None, 0.0

    def _on_frame(self, ball, width):
        """The servo, on the camera's thread: a frame in, a command out."""
        dog = self.dog
        cmd = self.follower.command(ball, width)
        dog.body.drive(cmd.linear, cmd.angular)
        resting = (ball is not None and abs(cmd.linear) < dog.p.rest_speed
                   and abs(cmd.angular) < dog.p.rest_speed)
        if not resting:
            self.rest_since = None
        elif self.rest_since is None:
            self.rest_since = dog.clock.now()
        self.frames += 1

    def _last_seen(self):
        seen = self.dog.eyes.last_seen()
        return self.entered if seen is None else max(seen, self.entered)

    def execute(self, ud):
        dog, p, clock = self.dog, self.dog.p, self.dog.clock
        self.entered, self.rest_since = clock.now(), None
        dog.eyes.follow(self._on_frame)
        try:
            while not clock.is_shutdown():
                now = clock.now()
                lost_at = self._last_seen() + p.lost_timeout
                if now >= lost_at:
                    dog.log.info('PLAY: ball lost for %.1f s', p.lost_timeout)
                    return 'lost'
                rest_since = self.rest_since
                if rest_since is not None and now >= rest_since + p.rest_time:
                    if not self.sweep_head():
                        break
                    continue
                deadline = lost_at if rest_since is None else min(lost_at,
                                                                  rest_since + p.rest_time)
                frames = self.frames
                clock.wait_until(lambda: self.frames != frames, deadline - now)
            return 'shutdown'
        finally:
            dog.eyes.follow(None)
            dog.body.stop()
            dog.body.head(0.0)

    def sweep_head(self):
        """Head to +angle, hold, -angle, hold, back to 0, the servo paused;
        False if the clock shut down meanwhile."""
        dog, p = self.dog, self.dog.p
        dog.log.info('PLAY: at the ball, moving the head')
        dog.eyes.follow(None)
        dog.body.stop()
        for angle in (p.head_angle, -p.head_angle, 0.0):
            dog.body.head(angle)
            if not dog.clock.sleep(p.head_hold):
                return False
        self.rest_since = None
        dog.eyes.follow(self._on_frame)
        return True


def build_state_machine(dog):
    """NORMAL (initial) <-> SLEEP, NORMAL -> PLAY -> NORMAL."""
    sm = smach.StateMachine(outcomes=['shutdown'])
    with sm:
        smach.StateMachine.add('NORMAL', Normal(dog),
                               transitions={'sleep': 'SLEEP', 'play': 'PLAY'})
        smach.StateMachine.add('SLEEP', Sleep(dog), transitions={'wake': 'NORMAL'})
        smach.StateMachine.add('PLAY', Play(dog), transitions={'lost': 'NORMAL'})
    return sm

"""Throttled refusal lines and the event clock's waits (no ROS)."""
import threading
import time

import pytest

from exp_assignment2.refusal import MAX_LINE, RefusalLog
from exp_assignment2.waiting import EventClock


class Timers(object):
    """A fake scheduler: timers run when the test says so."""

    def __init__(self):
        self.pending = []

    def __call__(self, delay, fn):
        self.pending.append((delay, fn))

    def run(self):
        pending, self.pending = self.pending, []
        for _, fn in pending:
            fn()


def make_log(now):
    lines, timers = [], Timers()
    return RefusalLog('/voice', lines.append, period=1.0, now=lambda: now[0],
                      schedule=timers), lines, timers


def test_a_burst_of_1000_refusals_makes_two_lines_with_the_count():
    now = [100.0]
    log, lines, timers = make_log(now)
    for i in range(1000):
        now[0] = 100.0 + i * 0.0005
        log('bad %d' % i)
    assert lines == ['/voice: bad 0']
    now[0] = 101.0
    timers.run()
    assert lines[1] == '/voice: 999 more refused in the last 1 s'
    assert len(lines) == 2


def test_refusals_a_second_apart_are_all_logged():
    now = [0.0]
    log, lines, timers = make_log(now)
    for i in range(5):
        now[0] = i * 1.0
        log('bad %d' % i)
    assert lines == ['/voice: bad %d' % i for i in range(5)]
    assert timers.pending == []


def test_the_held_count_rides_on_the_next_line():
    now = [0.0]
    log, lines, timers = make_log(now)
    log('a')
    now[0] = 0.5
    log('b')
    now[0] = 1.2
    log('c')
    assert lines == ['/voice: a', '/voice: c (and 1 more refused)']
    timers.run()                       # nothing left to report
    assert len(lines) == 2


def test_no_line_is_longer_than_the_cap():
    now = [0.0]
    log, lines, _ = make_log(now)
    log('x' * 100000)
    assert len(lines[0]) == MAX_LINE


def test_the_real_timer_flushes_in_wall_time():
    lines = []
    log = RefusalLog('/x', lines.append, period=0.05)
    for _ in range(10):
        log('bad')
    time.sleep(0.2)
    assert lines == ['/x: bad', '/x: 9 more refused in the last 0 s']


class Ticking(object):
    """A simulated clock driven by hand, as /clock drives a RosClock."""

    def __init__(self):
        self.t = 0.0
        self.clock = EventClock(now=lambda: self.t, ticking=True, wall_guard=5.0)

    def advance(self, dt):
        self.t += dt
        self.clock.tick(self.t)


def in_thread(fn):
    result = {}
    thread = threading.Thread(target=lambda: result.update(value=fn()))
    thread.start()
    return thread, result


def test_a_wait_ends_when_simulated_time_passes_its_deadline():
    sim = Ticking()
    thread, result = in_thread(lambda: sim.clock.wait_until(lambda: False, 1.0))
    time.sleep(0.05)
    sim.advance(0.5)
    time.sleep(0.05)
    assert thread.is_alive(), 'woke before its deadline'
    sim.advance(0.6)
    thread.join(1.0)
    assert not thread.is_alive() and result['value'] is False


def test_a_wait_ends_on_the_event_at_once():
    sim, flag = Ticking(), []
    thread, result = in_thread(lambda: sim.clock.wait_until(lambda: bool(flag), 100.0))
    time.sleep(0.05)
    start = time.monotonic()
    flag.append(1)
    sim.clock.notify()
    thread.join(1.0)
    assert result['value'] is True and time.monotonic() - start < 0.5


def test_shutdown_ends_every_wait():
    sim = Ticking()
    thread, result = in_thread(lambda: sim.clock.sleep(100.0))
    time.sleep(0.05)
    sim.clock.shutdown()
    thread.join(1.0)
    assert result['value'] is False


def test_a_tick_before_the_deadline_does_not_wake_waiters():
    sim, checks = Ticking(), []

    def predicate():
        checks.append(1)
        return False
    thread, _ = in_thread(lambda: sim.clock.wait_until(predicate, 10.0))
    time.sleep(0.05)
    for _ in range(50):
        sim.advance(0.01)
    time.sleep(0.05)
    assert len(checks) == 1, 'the predicate was re-checked on ticks before the deadline'
    sim.advance(10.0)
    thread.join(1.0)


def test_wall_time_waits_for_exactly_the_timeout():
    clock = EventClock()
    start = time.monotonic()
    assert clock.wait_until(lambda: False, 0.2) is False
    assert 0.19 <= time.monotonic() - start < 0.4


@pytest.mark.parametrize('timeout', [0.0, -1.0])
def test_a_wait_with_no_time_left_checks_once(timeout):
    clock = EventClock()
    assert clock.wait_until(lambda: True, timeout) is True
    assert clock.wait_until(lambda: False, timeout) is False

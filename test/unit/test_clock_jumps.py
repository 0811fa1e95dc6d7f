"""A ticking EventClock whose source jumps (a reset of the simulation, a bag
played in a loop) or that gets ticks from a second sender (a second /clock
publisher): the clock stands still across a jump and ignores the second
sender, so waits keep the time they had left and times kept stay comparable."""
import threading
import time

from exp_assignment2.waiting import EventClock

INTRUDER = (0.0, 2.0 ** 31 - 1, 2.0 ** 32 - 1)     # stamps a second publisher sent


class Source(object):
    """/clock by hand, with a hand-turned wall clock."""

    def __init__(self, t=100.0):
        self.wall, self.jumps = 0.0, []
        self.ignored = []
        self.clock = EventClock(now=lambda: 0.0, ticking=True, wall_guard=5.0,
                                on_jump=lambda a, b, who: self.jumps.append((a, b)),
                                on_ignored=lambda who, t: self.ignored.append((who, t)),
                                wall=lambda: self.wall)
        self.send(t)

    def send(self, t, wall_dt=0.01, sender='/gazebo'):
        self.wall += wall_dt
        self.clock.tick(t, sender)


def waiting(clock, seconds):
    result = {}
    thread = threading.Thread(target=lambda: result.update(
        value=clock.wait_until(lambda: False, seconds)), daemon=True)
    thread.start()
    time.sleep(0.05)
    return thread, result


def test_time_set_back_to_zero_keeps_the_time_a_wait_had_left():
    src = Source(100.0)
    thread, result = waiting(src.clock, 1.0)
    src.send(100.5)
    src.send(0.0)                       # reset: 0.5 s of the wait are left
    src.send(0.4)
    time.sleep(0.05)
    assert thread.is_alive(), 'the wait ended early'
    src.send(0.6)
    thread.join(1.0)
    assert not thread.is_alive() and result['value'] is False
    assert src.jumps == [(100.5, 0.0)]


def test_stamps_of_a_second_publisher_neither_end_nor_stall_a_wait():
    src = Source(30.0)
    thread, result = waiting(src.clock, 2.0)
    sim = 30.0
    for i in range(200):                # 2 s of stamps 0, 2^31-1, 2^32-1 between the simulator's
        sim += 0.005
        src.send(INTRUDER[i % 3], wall_dt=0.005, sender='/intruder')
        src.send(sim, wall_dt=0.005)
    time.sleep(0.05)
    assert thread.is_alive(), 'the intruder\'s stamps ended the wait'
    assert abs(src.clock.now() - 31.0) < 1e-6, 'the clock follows the simulator alone'
    assert len(src.ignored) == 200 and src.jumps == []
    for _ in range(120):                # the intruder is gone: 1.2 s more of simulated time
        sim += 0.01
        src.send(sim)
    thread.join(1.0)
    assert not thread.is_alive() and result['value'] is False


def test_the_clock_never_goes_back_and_follows_the_source_between_jumps():
    src = Source(50.0)
    seen = [src.clock.now()]
    for t in (50.1, 0.0, 0.1, 2.0 ** 32 - 1, 0.2, 0.3):
        src.send(t)
        seen.append(src.clock.now())
    assert seen == sorted(seen)
    assert abs(seen[-1] - 50.3) < 1e-9, seen


def test_stamps_of_the_source_are_brought_onto_the_clock_s_time_line():
    src = Source(100.0)
    src.send(0.0)
    src.send(1.0)
    assert abs(src.clock.from_source(0.5) - 100.5) < 1e-9
    assert src.clock.from_source(99.0) == src.clock.now(), 'a stamp from before the jump'


def test_a_fast_simulator_is_not_a_jump():
    src = Source(0.0)
    t = 0.0
    for _ in range(100):
        t += 0.5                        # 50 s of simulated time in 1 wall s
        src.send(t)
    src.send(t + 30.0, wall_dt=0.001)   # a node that lagged behind /clock
    src.send(t + 300.0, wall_dt=5.0)    # a process stopped for 5 s at 60x
    assert src.jumps == [] and src.clock.now() == t + 300.0


def test_a_huge_forward_step_is_a_jump():
    src = Source(10.0)
    src.send(2.0 ** 31 - 1)
    assert src.jumps == [(10.0, 2.0 ** 31 - 1)] and src.clock.now() == 10.0
    src.send(2.0 ** 31)
    assert src.clock.now() == 11.0


def test_another_sender_is_followed_once_the_first_is_silent():
    src = Source(100.0)
    src.send(5.0, wall_dt=0.5, sender='/rosbag')
    assert src.ignored == [('/rosbag', 5.0)] and src.clock.now() == 100.0
    src.send(6.0, wall_dt=1.0, sender='/rosbag')      # /gazebo silent for 1.5 s
    assert src.clock.sender == '/rosbag' and src.jumps == [(100.0, 6.0)]
    src.send(7.0, sender='/rosbag')
    assert src.clock.now() == 101.0

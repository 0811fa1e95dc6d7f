"""FramePace: at real_time_factor 0 a camera's frames wait for the consumers
that acknowledge them (no ROS; threads and a fake wall clock)."""
import threading
import time

from exp_assignment2.sim.pacing import FramePace


class Log(object):
    def __init__(self):
        self.lines = []

    def info(self, line):
        self.lines.append(('info', line))

    def warn(self, line):
        self.lines.append(('warn', line))


def send(pace, stamps):
    for s in stamps:
        pace.wait()
        pace.sent_frame(s)


def test_nobody_acknowledges_nobody_is_waited_for():
    pace = FramePace(window=2, now=lambda: 0.0)     # a wait would never end
    send(pace, range(1, 101))
    assert list(pace.sent) == [99, 100]             # only a window is kept


def test_a_consumer_let_go_keeps_the_stamps_bounded():
    ticks = iter(range(10 ** 6))            # a wall clock 1 s on at each look
    pace = FramePace(window=2, patience=1.0, now=lambda: float(next(ticks)))
    pace.sent_frame(1)
    pace.done('/state_machine', 1)
    send(pace, range(2, 2002))              # let go at the first wait, then not waited for
    assert len(pace.sent) == 2
    assert pace.consumers['/state_machine'][2] is False


def test_a_pause_with_nothing_pending_does_not_let_a_consumer_go():
    """Patience counts from when a wait began: a consumer that acknowledged
    everything 5 s ago (the world was paused) is waited for."""
    wall = [0.0]
    log = Log()
    pace = FramePace(window=2, patience=1.0, log=log, now=lambda: wall[0])
    pace.sent_frame(1)
    pace.done('/state_machine', 1)
    wall[0] = 5.0                           # paused for 5 s, nothing unacknowledged
    send(pace, [2, 3])
    waiter = threading.Thread(target=pace.wait)
    waiter.start()
    time.sleep(0.3)
    assert waiter.is_alive()                # held, not let go
    pace.done('/state_machine', 2)
    waiter.join(2.0)
    assert not waiter.is_alive()
    assert [line for level, line in log.lines if 'no frame' in line] == []


def test_a_consumer_that_joins_late_is_counted_from_the_newest_frame():
    """The state machine's announcement after rviz made the camera draw."""
    pace = FramePace(window=2, patience=10.0)
    send(pace, range(1, 6))
    pace.done('/state_machine', 0)          # its latched empty header
    send(pace, [6, 7])                      # not 5 frames behind: no wait
    passed = threading.Event()
    threading.Thread(target=lambda: (send(pace, [8]), passed.set())).start()
    assert not passed.wait(0.3)             # 6 and 7 unacknowledged: held
    pace.done('/state_machine', 6)
    assert passed.wait(2.0)


def test_an_acknowledgement_from_before_a_reset_is_ignored():
    pace = FramePace(window=2, patience=10.0)
    send(pace, [100, 200])
    pace.done('/sm', 200)
    pace.reset()                            # time back to 0
    pace.done('/sm', 300)                   # a frame still on its way: stale
    send(pace, [1, 2])
    passed = threading.Event()
    threading.Thread(target=lambda: (send(pace, [3]), passed.set())).start()
    assert not passed.wait(0.3)             # 1 and 2 unacknowledged: held
    pace.done('/sm', 1)
    assert passed.wait(2.0)


def test_a_consumer_holds_the_frames_it_is_a_window_behind():
    log = Log()
    pace = FramePace(window=2, patience=10.0, log=log)
    pace.sent_frame(1)
    pace.done('/state_machine', 1)
    assert log.lines == [('info', 'camera: /state_machine acknowledges frames: the simulation '
                                  'waits for it')]
    send(pace, [2, 3])                       # two unacknowledged: the next one waits
    passed = threading.Event()
    sender = threading.Thread(target=lambda: (send(pace, [4]), passed.set()))
    sender.start()
    assert not passed.wait(0.3)
    pace.done('/state_machine', 2)           # one frame done: one more may go
    assert passed.wait(2.0)
    sender.join()


def test_every_frame_reaches_a_slow_consumer_with_a_short_queue():
    """A consumer that, like rospy, reads what has come, keeps the newest
    ``queue`` of it and then works through those, loses none when its queue
    is as long as the window."""
    pace, window = FramePace(window=4, patience=10.0), 4
    inbox, lock, seen, lost = [], threading.Lock(), [], []
    stop = threading.Event()

    def consumer():
        while not stop.is_set() or inbox:
            with lock:
                batch, inbox[:] = inbox[:], []
            lost.extend(batch[:-window])                # rospy keeps the newest of a batch
            for stamp in batch[-window:]:
                time.sleep(0.002)                       # slower than the sender
                seen.append(stamp)
                pace.done('/slow', stamp)
            time.sleep(0.001)
    pace.sent_frame(0)
    pace.done('/slow', 0)
    thread = threading.Thread(target=consumer)
    thread.start()
    for stamp in range(1, 201):
        pace.wait()
        pace.sent_frame(stamp)
        with lock:
            inbox.append(stamp)
    stop.set()
    thread.join(10.0)
    assert lost == [] and seen == list(range(1, 201))


def test_a_silent_consumer_is_let_go_once_and_waited_for_again_when_back():
    wall = [0.0]
    log = Log()
    pace = FramePace(window=1, patience=1.0, log=log, now=lambda: wall[0])
    pace.sent_frame(1)
    pace.done('/state_machine', 1)
    pace.sent_frame(2)                      # unacknowledged: a window of 1 is full
    waiter = threading.Thread(target=pace.wait)
    waiter.start()
    time.sleep(0.2)
    assert waiter.is_alive()
    wall[0] = 1.5                           # silent for 1.5 s of wall time
    waiter.join(2.0)
    assert not waiter.is_alive()
    assert log.lines[-1] == ('info', 'camera: /state_machine acknowledged no frame for 1.5 s: '
                                     'not waiting for it')
    send(pace, [3, 4, 5])                   # not waited for, no more lines
    assert len(log.lines) == 2
    pace.done('/state_machine', 5)          # back: waited for again
    assert log.lines[-1] == ('info', 'camera: /state_machine acknowledges frames: the '
                                     'simulation waits for it')
    pace.sent_frame(6)
    waiter = threading.Thread(target=pace.wait)
    waiter.start()
    time.sleep(0.2)
    assert waiter.is_alive()
    pace.done('/state_machine', 6)
    waiter.join(2.0)
    assert not waiter.is_alive()


def test_time_going_back_forgets_the_stamps():
    pace = FramePace(window=2, patience=10.0)
    pace.sent_frame(10 ** 9)
    pace.done('/sm', 10 ** 9)
    pace.reset()                            # reset_simulation: stamps start again at 0
    pace.sent_frame(1)                      # one unacknowledged of 2: no wait
    done = threading.Event()
    threading.Thread(target=lambda: (pace.wait(), done.set())).start()
    assert done.wait(1.0)
    pace.sent_frame(2)                      # two: waits until the consumer is back
    done.clear()
    threading.Thread(target=lambda: (pace.wait(), done.set())).start()
    assert not done.wait(0.3)
    pace.done('/sm', 2)
    assert done.wait(1.0)


def test_a_consumer_announced_before_the_first_frame_holds_the_first_frames():
    pace = FramePace(window=3, patience=10.0)
    pace.done('/state_machine', 0)          # its latched empty header, before any frame
    send(pace, [1, 2, 3])
    passed = threading.Event()
    threading.Thread(target=lambda: (send(pace, [4]), passed.set())).start()
    assert not passed.wait(0.3)             # its first frames are slow: they wait
    pace.done('/state_machine', 1)
    assert passed.wait(2.0)

"""The simulator's publisher queues: rospy's, without a yield per message
(needs Debian's rospy; no master)."""
import threading
import time

import pytest

pytest.importorskip('rospy')

from exp_assignment2.ros import steady_publishing  # noqa: E402


class FakeTransport(object):
    """Stands in for a TCPROS transport: records what it sends."""

    def __init__(self):
        self.sent, self.done, self.endpoint_id = [], False, 'fake'
        self.cleanup = None
        self.arrived = threading.Event()

    def set_cleanup_callback(self, fn):
        self.cleanup = fn

    def write_data(self, data):
        self.sent.append(data)
        self.arrived.set()


def test_messages_arrive_in_order_and_the_oldest_are_dropped_when_full():
    transport, release = FakeTransport(), threading.Event()
    send = transport.write_data
    transport.write_data = lambda data: (release.wait(5), send(data))
    conn = steady_publishing.SteadyQueuedConnection(transport, 3)
    conn.write_data(b'first')               # taken by the sender, which blocks
    deadline = time.monotonic() + 5
    while conn._queue and time.monotonic() < deadline:
        time.sleep(0.01)
    for i in range(5):                      # three places: 0 and 1 are dropped
        conn.write_data(b'%d' % i)
    release.set()
    while len(transport.sent) < 4 and time.monotonic() < deadline:
        time.sleep(0.01)
    assert transport.sent == [b'first', b'2', b'3', b'4']
    transport.done = True
    with conn._lock:
        conn._cond_data_available.notify()


def test_write_data_does_not_sleep(monkeypatch):
    calls = []
    monkeypatch.setattr(time, 'sleep', lambda s: calls.append(s))
    transport = FakeTransport()
    conn = steady_publishing.SteadyQueuedConnection(transport, 1)
    conn.write_data(b'a')
    assert calls == []
    transport.done = True
    with conn._lock:
        conn._cond_data_available.notify()


def test_install_replaces_rospys_queue_for_new_connections():
    import rospy.topics
    original = rospy.topics.QueuedConnection
    try:
        steady_publishing.install()
        assert rospy.topics.QueuedConnection is steady_publishing.SteadyQueuedConnection
    finally:
        rospy.topics.QueuedConnection = original

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


class SocketTransport(FakeTransport):
    """A transport over one end of a socket pair, as TCPROS's: sendall and its counts."""

    def __init__(self, sock):
        FakeTransport.__init__(self)
        self.socket, self.stat_bytes, self.stat_num_msg = sock, 0, 0

    def write_data(self, data):
        self.sent.append(bytes(data))
        self.socket.sendall(data)
        self.stat_bytes += len(data)
        self.stat_num_msg += 1


def framed(i, size):
    """A TCPROS message: its length, then ``size`` bytes of ``i``."""
    import struct
    return struct.pack('<I', size) + bytes([i % 256]) * size


def read_messages(sock, count):
    import struct
    data, found = b'', []
    sock.settimeout(10)
    while len(found) < count:
        data += sock.recv(1 << 20)
        while len(data) >= 4 and len(data) >= 4 + struct.unpack('<I', data[:4])[0]:
            size = struct.unpack('<I', data[:4])[0]
            found.append(data[4:4 + size])
            data = data[4 + size:]
    return found


def tcp_pair():
    """Two ends of a loopback TCP connection, as TCPROS's."""
    import socket
    with socket.socket() as server:
        server.bind(('127.0.0.1', 0))
        server.listen(1)
        ours = socket.create_connection(server.getsockname())
        theirs, _ = server.accept()
    return ours, theirs


def close(conn, transport):
    transport.done = True
    with conn._lock:
        conn._cond_data_available.notify()


def test_a_socket_that_takes_it_gets_it_at_once_from_the_publishing_thread():
    ours, theirs = tcp_pair()
    transport = SocketTransport(ours)
    conn = steady_publishing.SteadyQueuedConnection(transport, 10)
    try:
        for i in range(1000):       # a second of /clock, read after
            conn.write_data(framed(i, 8))
        assert [m[0] for m in read_messages(theirs, 1000)] == [i % 256 for i in range(1000)]
        assert transport.sent == []             # the sender thread never woke
        assert (transport.stat_num_msg, transport.stat_bytes) == (1000, 12000)
    finally:
        close(conn, transport)
        ours.close(), theirs.close()


def test_a_slow_reader_gets_whole_messages_in_order_and_only_whole_ones_dropped():
    import socket
    ours, theirs = tcp_pair()
    ours.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 65536)
    theirs.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 65536)
    transport = SocketTransport(ours)
    conn = steady_publishing.SteadyQueuedConnection(transport, 2)
    try:
        # a large image, only part of which the socket takes, then more behind it
        for i in range(6):
            conn.write_data(framed(i, 400000))
        got = read_messages(theirs, 3)
        assert [(m[0], len(m)) for m in got] == [(0, 400000), (4, 400000), (5, 400000)]
        # the sender thread counts a message once its sendall returns, which may
        # be a moment after the reader has the last byte
        deadline = time.monotonic() + 5
        while transport.stat_num_msg < 3 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert transport.stat_num_msg == 3 and transport.stat_bytes == 3 * 400004
        conn.write_data(framed(9, 8))       # all written: at once again
        assert read_messages(theirs, 1) == [bytes([9]) * 8]
    finally:
        close(conn, transport)
        ours.close(), theirs.close()


def test_a_closed_subscriber_is_an_error_at_the_next_publish():
    ours, theirs = tcp_pair()
    transport = SocketTransport(ours)
    conn = steady_publishing.SteadyQueuedConnection(transport, 10)
    theirs.close()
    try:
        deadline = time.monotonic() + 5
        with pytest.raises(OSError):
            while time.monotonic() < deadline:
                conn.write_data(framed(1, 8))
                time.sleep(0.01)
    finally:
        close(conn, transport)
        ours.close()


def test_a_socket_with_a_timeout_is_left_to_the_sender_thread():
    """Python's send on a socket with a timeout waits for room: never from the loop."""
    ours, theirs = tcp_pair()
    ours.settimeout(5.0)
    transport = SocketTransport(ours)
    conn = steady_publishing.SteadyQueuedConnection(transport, 10)
    try:
        conn.write_data(framed(3, 8))
        assert read_messages(theirs, 1) == [bytes([3]) * 8]
        assert transport.sent == [framed(3, 8)]     # written by the sender thread
    finally:
        close(conn, transport)
        ours.close(), theirs.close()

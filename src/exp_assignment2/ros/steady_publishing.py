"""Publishing from a busy loop without handing the GIL away on every message.

rospy's publisher queues (``queue_size`` set, as every publisher here has)
end each ``publish`` to each subscriber connection with ``time.sleep(0)``,
"to yield the rest of the thread quantum" to the sending thread. In the
simulator that is ten connections or more per physics step (``/clock`` alone
goes to every node): each yield hands the GIL to the camera's worker or a
sender thread and the loop waits up to a switch interval to get it back.
Profiled at real_time_factor 0, the loop spent about 40 % of its time there.

And each message woke its connection's sender thread: a thousand ``/clock``
messages a second to every node, each a thread wake-up, a GIL hand-over and
a ``sendall`` of 12 bytes. Here a message whose connection has nothing
queued and nothing being written is sent at once from the publishing thread,
without blocking (``MSG_DONTWAIT``): a local subscriber's socket takes it
whole. Only what the socket does not take (a subscriber that reads slowly,
a large image) goes to the sender thread as before, after whatever part was
sent: the bytes on the wire and their order are rospy's.

:func:`install` makes the process's publisher queues these: queue sizes,
drops of the oldest message and errors (raised at the next publish, the
connection closed by rospy's own code) are as before.
"""
import socket

import rospy.topics
from rospy.impl.tcpros_pubsub import QueuedConnection


class SteadyQueuedConnection(QueuedConnection):
    """rospy's QueuedConnection that sends at once when it can and never yields."""

    def __init__(self, connection, queue_size):
        self._writing = False       # the sender thread has data out of the queue
        self._rest = None           # what a send at once left: sent next, never dropped
        QueuedConnection.__init__(self, connection, queue_size)

    def write_data(self, data):
        with self._lock:
            if self._error:     # an error of the sender thread surfaces here, as in rospy
                error, self._error = self._error, None
                raise error
            if not self._queue and not self._writing and self._rest is None:
                sent = self._send_now(data)
                if sent == len(data):
                    self._connection.stat_bytes += sent
                    self._connection.stat_num_msg += 1
                    return True
                if sent:        # a part is out: the rest must follow it, whatever comes
                    self._connection.stat_bytes += sent
                    self._rest = memoryview(data)[sent:]
                    self._cond_data_available.notify()
                    return True
            if self._queue_size > 0 and len(self._queue) == self._queue_size:
                del self._queue[0]      # drop the oldest, as rospy does
            self._queue.append(data)
            self._cond_data_available.notify()
        return True

    def _send_now(self, data):
        """Bytes of ``data`` the socket took without waiting (0: none, or an
        error the sender thread meets again and handles as rospy does)."""
        sock = getattr(self._connection, 'socket', None)
        # a socket with a timeout would wait for room in Python's send: none here
        if sock is None or self._connection.done or sock.gettimeout() is not None:
            return 0
        try:
            return sock.send(data, socket.MSG_DONTWAIT)
        except OSError:
            return 0

    def _run(self):
        connection = self._connection
        while not connection.done:
            with self._lock:
                while not self._queue and self._rest is None and not connection.done:
                    self._cond_data_available.wait()
                rest, queue = self._rest, self._queue
                self._rest, self._queue = None, []
                self._writing = True
            try:
                if rest is not None:
                    self._write(rest.tobytes())
                for data in queue:
                    self._write(data)
            finally:
                with self._lock:
                    self._writing = False

    def _write(self, data):
        try:        # rospy's transport counts the message (a rest: its part counted too)
            self._connection.write_data(data)
        except Exception as exc:    # noqa: BLE001 -- raised at the next publish, as rospy does
            with self._lock:
                self._error = exc


def install():
    """Use :class:`SteadyQueuedConnection` for every connection made from now
    on in this process (call before publishers get subscribers)."""
    rospy.topics.QueuedConnection = SteadyQueuedConnection

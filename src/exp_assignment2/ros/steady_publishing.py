"""Publishing from a busy loop without handing the GIL away on every message.

rospy's publisher queues (``queue_size`` set, as every publisher here has)
end each ``publish`` to each subscriber connection with ``time.sleep(0)``,
"to yield the rest of the thread quantum" to the sending thread. In the
simulator that is ten connections or more per physics step (``/clock`` alone
goes to every node): each yield hands the GIL to the camera's worker or a
sender thread and the loop waits up to a switch interval to get it back.
Profiled at real_time_factor 0, the loop spent about 40 % of its time there.

:func:`install` makes the process's publisher queues plain queues: the
message is queued and the sender thread woken, as before, but the publishing
thread goes on; the sender runs at the interpreter's next thread switch (at
most ``sys.getswitchinterval()`` later, 5 ms) or as soon as the loop waits.
Nothing else changes: queue sizes, drops of the oldest message, errors.
"""
import rospy.topics
from rospy.impl.tcpros_pubsub import QueuedConnection


class SteadyQueuedConnection(QueuedConnection):
    """rospy's QueuedConnection whose ``write_data`` does not yield."""

    def write_data(self, data):
        with self._lock:
            if self._error:     # an error of the sender thread surfaces here, as in rospy
                error, self._error = self._error, None
                raise error
            if self._queue_size > 0 and len(self._queue) == self._queue_size:
                del self._queue[0]      # drop the oldest, as rospy does
            self._queue.append(data)
            self._cond_data_available.notify()
        return True


def install():
    """Use :class:`SteadyQueuedConnection` for every connection made from now
    on in this process (call before publishers get subscribers)."""
    rospy.topics.QueuedConnection = SteadyQueuedConnection

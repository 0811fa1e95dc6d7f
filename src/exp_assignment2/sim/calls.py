"""Work handed to the simulation thread, the only one that touches pybullet
(no ROS, no pybullet here): other threads queue calls, the loop runs them
between steps."""
import collections
import threading


class Calls(object):
    """A queue of calls for one thread (thread-safe to fill)."""

    def __init__(self):
        self._queue = collections.deque()

    def soon(self, fn):
        """Queue ``fn()`` for the simulation thread."""
        self._queue.append(fn)

    def and_wait(self, fn, timeout=5.0):
        """Run ``fn()`` in the simulation thread and return its result (or raise
        what it raised); TimeoutError if the loop does not get to it."""
        done, box = threading.Event(), {}

        def call():
            try:
                box['value'] = fn()
            except Exception as exc:        # handed back to the caller's thread
                box['error'] = exc
            done.set()
        self.soon(call)
        if not done.wait(timeout):
            raise TimeoutError('the simulation loop did not answer within %.0f s' % timeout)
        if 'error' in box:
            raise box['error']
        return box.get('value')

    def run(self):
        """Run what is queued (the simulation thread, between steps)."""
        while self._queue:
            self._queue.popleft()()

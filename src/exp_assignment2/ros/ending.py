"""How the package's nodes end when ROS shuts them down."""
import logging
import os
import signal
import sys
import threading

import rospy


class DeferredShutdown(object):
    """SIGINT and SIGTERM shut ROS down on a thread of their own.

    rospy's handler runs ``signal_shutdown`` inside the signal handler, that
    is in the main thread, in whatever frame the signal interrupted. That
    frame may hold the lock of a publisher's queue (``publish`` from the main
    thread, as the simulator does with ``/clock`` every step): closing that
    publisher then waits for the same lock, and the node hangs until roslaunch
    escalates to SIGKILL 17 s later. Seen in 3 of 26 rostests in one run.

    Here the handler only writes the signal's number to a pipe (no lock, no
    allocation that could wait) and a thread started with the handler calls
    ``rospy.signal_shutdown('signal-N')``, with rospy's reason, once the main
    thread has left the frame. rospy's own handler is not chained: for SIGINT
    it only turned the KeyboardInterrupt it raises into nothing.
    """

    SIGNALS = (signal.SIGINT, signal.SIGTERM)

    def __init__(self):
        self._read = self._write = None
        self.done = threading.Event()   # signal_shutdown has returned
        self.signalled = False

    def register(self):
        """Install the handlers (main thread only, as rospy's)."""
        if self._read is None:
            self._read, self._write = os.pipe()
            os.set_blocking(self._write, False)
            threading.Thread(target=self._run, name='signal shutdown', daemon=True).start()
        for sig in self.SIGNALS:
            signal.signal(sig, self._handle)

    def _handle(self, signum, frame):
        self.signalled = True
        try:
            os.write(self._write, bytes((signum,)))
        except OSError:         # the pipe is full: a shutdown is on its way already
            pass

    def _run(self):
        while True:
            signum = os.read(self._read, 1)[0]
            rospy.core.signal_shutdown('signal-%d' % signum)
            self.done.set()

    def wait(self, timeout=10.0):
        """After a signal, wait until its shutdown hooks have run (a node's
        last report is one of them)."""
        if self.signalled:
            self.done.wait(timeout)


DEFERRED = DeferredShutdown()


def run_until_shutdown(body):
    """Run ``body()`` until it returns, then leave the process.

    An error raised because ROS shut down under ``body`` (a topic closed in
    the middle of a publish, as ``rosnode kill`` can do to a state that is
    just sending a goal; ``init_node`` interrupted when roslaunch ends the
    launch while the node starts) is the end of the node, not an error: it
    is dropped. Every node's script runs its ``main`` here.

    The process then leaves at once, without the interpreter's teardown:
    with OpenCV loaded (Debian builds it with TBB), that teardown sometimes
    aborts in C++ after ``rosnode kill`` ("terminate called without an
    active exception", exit code -6). Logs are flushed first.
    """
    # init_node (in body) registers rospy's handlers through this name
    rospy.core.register_signals = DEFERRED.register
    code = 0
    try:
        body()
    except Exception:
        # requested, not is_shutdown(): a publish during roslaunch's shutdown was
        # seen to raise 'topic was closed' while is_shutdown() was still False
        if not rospy.core.is_shutdown_requested():
            raise
    except SystemExit as stop:
        code = stop.code if isinstance(stop.code, int) else 1
    DEFERRED.wait()
    sys.stdout.flush()
    sys.stderr.flush()
    logging.shutdown()
    os._exit(code)

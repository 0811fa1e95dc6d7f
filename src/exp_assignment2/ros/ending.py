"""How the package's nodes end when ROS shuts them down."""
import logging
import os
import sys

import rospy


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
    sys.stdout.flush()
    sys.stderr.flush()
    logging.shutdown()
    os._exit(code)

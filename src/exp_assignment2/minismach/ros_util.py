"""smach_ros's glue between SMACH and rospy (``smach_ros.util`` and what
``import smach_ros`` does to smach).

* :func:`hand_rospy_to`: what importing smach_ros does, SMACH's log to
  rospy's and rospy's shutdown as SMACH's shutdown check, so a machine's
  reports reach the node's ROS log and it stops stepping at shutdown;
* :func:`set_preempt_handler`: a container preempted when rospy shuts down.
"""
import threading
import time

import rospy

WAITING = 'Received shutdown request... sent preempt... waiting for state machine to terminate.'
WAIT_STEP = 0.05        # wall s between looks at a preempted machine that still runs


def hand_rospy_to(smach):
    """``smach.set_loggers(rospy's)`` and ``smach.set_shutdown_check(rospy.is_shutdown)``,
    as smach_ros's import does (a ``smach`` without them is left alone)."""
    if hasattr(smach, 'set_loggers'):
        smach.set_loggers(rospy.loginfo, rospy.logwarn, rospy.logdebug, rospy.logerr)
    if hasattr(smach, 'set_shutdown_check'):
        smach.set_shutdown_check(rospy.is_shutdown)


def as_duration(value):
    """A time span in seconds (or None) taken as smach_ros takes a rospy.Duration."""
    if value is None or isinstance(value, rospy.Duration):
        return value
    return rospy.Duration.from_sec(float(value))


def set_preempt_handler(sc):
    """Preempt the container ``sc`` when rospy shuts down (Ctrl-C, roslaunch's
    end, ``rospy.signal_shutdown``), and hold the shutdown until it has
    stopped, saying so once a second, as smach_ros does.

    rospy calls the handler among its client shutdown hooks, before
    ``rospy.is_shutdown()`` becomes true, so the states end on the preempt
    with rospy still working. Unlike smach_ros, the wait is in wall time (a
    simulator whose clock stops first cannot hold it), and it is skipped when
    the handler runs in the very thread that runs the machine (a signal in a
    node that calls ``sm.execute()`` itself), where it could never end.
    """
    rospy.core.add_client_shutdown_hook(lambda: _preempt_and_wait(sc))


def _preempt_and_wait(sc):
    sc.request_preempt()
    if getattr(sc, '_executor', None) is threading.current_thread():
        return
    running = getattr(sc, 'is_running', None)      # SMACH's StateMachine has it
    while running is not None and running():
        rospy.loginfo(WAITING)
        deadline = time.monotonic() + 1.0
        while running() and time.monotonic() < deadline:
            time.sleep(WAIT_STEP)

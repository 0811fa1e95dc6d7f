"""The one place the package imports SMACH from.

``smach`` is the real library when it is importable (a Noetic install from
the ROS repositories has it) and :mod:`exp_assignment2.minismach` otherwise
(Debian bookworm has none). ``IS_REAL_SMACH`` says which.
"""
try:
    import smach  # noqa: F401  (re-exported)
    IS_REAL_SMACH = True
except ImportError:
    from exp_assignment2 import minismach as smach  # noqa: F401
    IS_REAL_SMACH = False


def report_active_state(sm, callback):
    """Call ``callback(label)`` whenever ``sm`` enters a state (also the first).

    Works with the real smach and with minismach: both call start and
    transition callbacks as ``cb(userdata, active_states)``.
    """
    def on_change(_userdata, active_states, *_args):
        if active_states:
            callback(active_states[0])
    sm.register_start_cb(on_change)
    sm.register_transition_cb(on_change)


def log_to(info, warn, debug, error):
    """Route SMACH's own log lines (each container's start, transitions, end) to these
    functions, as smach_ros does for rospy: without it SMACH prints them on stdout."""
    smach.set_loggers(info, warn, debug, error)

"""``smach_ros`` for the original-code environment: only what the original uses.

This directory is on PYTHONPATH only inside tools/original_env/shell.sh, and
only when ``import smach_ros`` failed there before (a real smach_ros always
wins). The original assignment creates an introspection server for
smach_viewer and never relies on it, so :class:`IntrospectionServer` is kept
with its real signature and does nothing (smach_viewer shows nothing).
"""
import smach  # noqa: F401  (as the real smach_ros, it needs smach)

__all__ = ['IntrospectionServer']


class IntrospectionServer(object):
    """``IntrospectionServer(server_name, state, path)``; start/stop/clear do nothing."""

    def __init__(self, server_name, state, path):
        self._server_name = server_name
        self._state = state
        self._path = path

    def start(self):
        pass

    def stop(self):
        pass

    def clear(self):
        pass


def __getattr__(name):
    raise AttributeError(
        "smach_ros.%s is not provided by the original-code environment's "
        "smach_ros replacement (tools/original_env, Debian has no smach_ros): "
        "it only has a no-op IntrospectionServer" % name)

"""``smach_ros`` for the original-code environment: exp_assignment2's states.

This directory is on PYTHONPATH only in the original-code environment, and
only when ``import smach_ros`` failed there before (a real smach_ros always
wins). SimpleActionState, ServiceState, MonitorState, ActionServerWrapper and
IntrospectionServer come from ``exp_assignment2.minismach``'s ``ros_states``,
``ros_monitor`` and ``ros_servers`` (see them for what each does; the
introspection server publishes what smach_viewer reads, in smach_msgs' stand-in).
Beside a real smach, whose states they are not, only IntrospectionServer.
"""
import importlib

import smach

_shim = getattr(smach, '_impl', None)       # exp_assignment2's smach (original_env/shims)
_package = _shim.__name__ if _shim else 'exp_assignment2.minismach'
_parts = {name: importlib.import_module('%s.%s' % (_package, module))
          for module, names in (('ros_states', ('SimpleActionState', 'ServiceState')),
                                ('ros_monitor', ('MonitorState',)),
                                ('ros_servers', ('ActionServerWrapper', 'IntrospectionServer')))
          for name in names}

__all__ = (['SimpleActionState', 'ServiceState', 'MonitorState', 'ActionServerWrapper',
            'IntrospectionServer']
           if _shim else ['IntrospectionServer'])
globals().update((name, getattr(_parts[name], name)) for name in __all__)


def __getattr__(name):
    raise AttributeError(
        "smach_ros.%s is not provided by exp_assignment2's smach_ros replacement "
        "(the original-code environment's, Debian has no smach_ros); available: %s"
        % (name, ', '.join(__all__)))

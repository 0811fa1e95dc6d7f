"""``smach_ros`` for the original-code environment: exp_assignment2's states.

This directory is on PYTHONPATH only in the original-code environment, and
only when ``import smach_ros`` failed there before (a real smach_ros always
wins). Every name of smach_ros comes from ``exp_assignment2.minismach``:
SimpleActionState and ServiceState (``ros_states``), MonitorState
(``ros_monitor``), ConditionState (``ros_condition``), ActionServerWrapper
(``ros_servers``), IntrospectionServer and IntrospectionClient
(``introspection``: what smach_viewer reads, in smach_msgs' stand-in) and
set_preempt_handler (``ros_util``); each module also under smach_ros' name
(``smach_ros.simple_action_state``, ...). Importing it hands rospy to smach
as smach_ros does: smach's log goes to rospy's, and rospy's shutdown stops
its containers. Beside a real smach, whose states they are not, only what
needs no state of ours: IntrospectionServer, IntrospectionClient,
set_preempt_handler.
"""
import importlib
import sys as _sys

import rospy  # noqa: F401  (smach_ros' own import)
import smach

_shim = getattr(smach, '_impl', None)       # exp_assignment2's smach (original_env/shims)
_package = _shim.__name__ if _shim else 'exp_assignment2.minismach'
# smach_ros' modules: (its name, the minismach module, its names, a state of ours)
_MODULES = (('util', 'ros_util', ('set_preempt_handler',), False),
            ('introspection', 'introspection', ('IntrospectionClient', 'IntrospectionServer'),
             False),
            ('action_server_wrapper', 'ros_servers', ('ActionServerWrapper',), True),
            ('simple_action_state', 'ros_states', ('SimpleActionState',), True),
            ('service_state', 'ros_states', ('ServiceState',), True),
            ('monitor_state', 'ros_monitor', ('MonitorState',), True),
            ('condition_state', 'ros_condition', ('ConditionState',), True))

__all__ = []
for _name, _module, _names, _ours in _MODULES:
    if _ours and not _shim:
        continue
    _part = importlib.import_module('%s.%s' % (_package, _module))
    globals()[_name] = _sys.modules[__name__ + '.' + _name] = _part
    globals().update((name, getattr(_part, name)) for name in _names)
    __all__ += _names

importlib.import_module(_package + '.ros_util').hand_rospy_to(smach)


def __getattr__(name):
    raise AttributeError(
        "smach_ros.%s is not provided by exp_assignment2's smach_ros replacement "
        "(the original-code environment's, Debian has no smach_ros); available: %s"
        % (name, ', '.join(__all__)))

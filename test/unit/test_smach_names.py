"""Every public name of the real smach and smach_ros is in the replacement.

The lists are written by hand from executive_smach's noetic-devel
``smach/src/smach/__init__.py`` and ``smach_ros/src/smach_ros/__init__.py``
(their imports; smach_ros' ``__all__``), and the ``__all__`` of the modules
those import from. A module the package imports binds its name too
(``smach.state_machine``): those are listed as modules. smach_ros' own
imports (roslib, rospy, smach) are its tools, not its names. What each name
does is tested in test_minismach*.py and test_smach_ros_glue.py.
"""
import os

import pytest

from exp_assignment2 import minismach
from original_env_helpers import PYTHON, base_env, original_env, run

SMACH = {   # module -> the names the package imports from it
    'log': ('set_loggers', 'loginfo', 'logwarn', 'logerr', 'logdebug'),
    'exceptions': ('InvalidTransitionError', 'InvalidStateError', 'InvalidConstructionError',
                   'InvalidUserCodeError'),
    'state': ('State', 'CBState'),
    'user_data': ('UserData', 'Remapper'),
    'container': ('Container',),
    'util': ('is_shutdown', 'set_shutdown_check', 'has_smach_interface', 'cb_interface',
             'CBInterface'),
    'state_machine': ('StateMachine',),
    'sequence': ('Sequence',),
    'concurrence': ('Concurrence',),
    'iterator': ('Iterator',),
}
SMACH_MODULE_ALL = {'exceptions': ('SmachError',)}     # in a module's __all__ only
SMACH_ROS = {
    'util': ('set_preempt_handler',),
    'action_server_wrapper': ('ActionServerWrapper',),
    'introspection': ('IntrospectionClient', 'IntrospectionServer'),
    'simple_action_state': ('SimpleActionState',),
    'service_state': ('ServiceState',),
    'monitor_state': ('MonitorState',),
    'condition_state': ('ConditionState',),
}
SMACH_ROS_ALL = ('set_preempt_handler', 'ActionServerWrapper', 'IntrospectionClient',
                 'IntrospectionServer', 'SimpleActionState', 'ServiceState', 'MonitorState',
                 'ConditionState')


def names(table):
    return sorted(name for found in table.values() for name in found)


def test_the_lists_agree_with_smach_ros_all():
    assert names(SMACH_ROS) == sorted(SMACH_ROS_ALL)


def test_minismach_has_every_name_of_smach():
    assert [name for name in names(SMACH) if not hasattr(minismach, name)] == []
    assert set(names(SMACH)) <= set(minismach.__all__) <= set(dir(minismach))


# What the original-code environment's smach and smach_ros give a student's code.
CHECK = '''
import importlib, smach, smach_ros
from smach import *
from smach_ros import *
for package, table, everything in ((smach, %r, %r), (smach_ros, %r, %r)):
    for module, found in sorted(table.items()):
        sub = importlib.import_module(package.__name__ + '.' + module)
        assert getattr(package, module) is sub, module
        for name in found:
            if not hasattr(package, name) or not hasattr(sub, name):
                print('MISSING', package.__name__, module, name)
    for name in everything:
        if name not in globals():
            print('NOT STARRED', package.__name__, name)
print('CHECKED')
'''


@pytest.mark.skipif(not os.path.exists(PYTHON), reason='needs Debian python3')
def test_the_shims_have_every_name_and_module_of_smach_and_smach_ros():
    env = original_env(base_env())
    if 'smach: shim' not in env['EXP2_ORIGINAL_ENV']:
        pytest.skip('a real smach is installed here')
    smach_table = dict(SMACH, **{k: SMACH[k] + v for k, v in SMACH_MODULE_ALL.items()})
    proc = run(CHECK % (smach_table, names(SMACH), SMACH_ROS, SMACH_ROS_ALL), env)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == ['CHECKED']

"""``smach`` for the original-code environment: exp_assignment2's SMACH-compatible module.

This directory is on PYTHONPATH only in the original-code environment, and
only when ``import smach`` failed there before (a real smach always wins).
Everything comes from ``exp_assignment2.minismach``: every name of SMACH's
package (State, StateMachine, Sequence, Concurrence, Iterator, CBState,
cb_interface, CBInterface, UserData, Remapper, the SMACH exceptions,
set_loggers and the log functions, set_shutdown_check, is_shutdown, ...), and
its modules under SMACH's names (``smach.state``, ``smach.state_machine``,
``smach.log``, ``smach.util``, ...), for ``from smach.state import State``.
"""
import importlib
import sys as _sys

try:
    _impl = importlib.import_module('exp_assignment2.minismach')
except ImportError:
    # ``exp_assignment2`` may be the user's own package of the same name (the
    # original assignment's): load the package from this repository instead.
    import importlib.util as _util
    import os as _os
    _dir = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), *(
        [_os.pardir] * 4 + ['minismach']))
    _spec = _util.spec_from_file_location('exp2_minismach', _os.path.join(_dir, '__init__.py'),
                                          submodule_search_locations=[_dir])
    _impl = _util.module_from_spec(_spec)
    _sys.modules[_spec.name] = _impl
    _spec.loader.exec_module(_impl)

__all__ = list(_impl.__all__)
# the log functions and is_shutdown change with set_loggers, set_shutdown_check:
# read from minismach when used (__getattr__), not copied
globals().update((name, getattr(_impl, name)) for name in __all__ if name not in _impl.CURRENT)

# SMACH's modules, each the minismach module that holds its names
for _name, _module in (('log', 'log'), ('util', 'util'), ('exceptions', 'states'),
                       ('state', 'states'), ('user_data', 'states'),
                       ('container', 'machine'), ('state_machine', 'machine'),
                       ('sequence', 'machine'), ('concurrence', 'concurrence'),
                       ('iterator', 'iterator')):
    globals()[_name] = _sys.modules[__name__ + '.' + _name] = _sys.modules[
        _impl.__name__ + '.' + _module]


def __getattr__(name):
    if name in _impl.CURRENT:
        return _impl.current(name)
    # Say clearly which part of SMACH this replacement lacks.
    raise AttributeError(
        "smach.%s is not provided by exp_assignment2's SMACH replacement "
        "(the original-code environment's, Debian has no smach); available: %s"
        % (name, ', '.join(__all__)))

"""A small, SMACH-compatible state machine library.

Debian bookworm ships no ``smach``. The states of this package are written
against the SMACH API, and :mod:`exp_assignment2.smach_api` uses the real
``smach`` when it is importable and this module otherwise. Every name of
SMACH's package is here (test/unit/test_smach_names.py lists the real one's):

* :class:`State` with outcomes, input/output/io keys and preemption,
* :class:`CBState` and :func:`cb_interface`,
* :class:`StateMachine` (``with sm:`` + :meth:`StateMachine.add`), userdata
  with remapping, start/transition/termination callbacks,
* :class:`Sequence` (states in the order added, joined by a connector
  outcome), :class:`Concurrence` (states at once, an outcome map or
  callback, a child termination callback) and :class:`Iterator` (one state
  once per item),
* the error classes :class:`InvalidStateError`,
  :class:`InvalidTransitionError`, :class:`InvalidUserCodeError`,
* what ``smach.log`` and ``smach.util`` give: ``set_loggers`` and the four
  log functions (:mod:`.log`), ``set_shutdown_check`` and ``is_shutdown``,
  ``cb_interface``, ``CBInterface``, ``has_smach_interface`` (:mod:`.util`).

The semantics follow SMACH: the first state added is the initial one, an
outcome without a transition is the container's outcome of the same name, a
state returning an outcome it did not register is an
:class:`InvalidTransitionError`, and an exception from user code is wrapped
in :class:`InvalidUserCodeError`. The containers report what they do through
the log functions (printed, until ``set_loggers``; smach_ros hands rospy's)
and stop once ``is_shutdown()`` is true. ``loginfo``, ``logwarn``,
``logdebug``, ``logerr`` and ``is_shutdown`` are the ones now in use, looked
up when read (SMACH rebinds its module's names).
"""
# relative imports: original_env/shims/smach loads this package by its path
# when ``exp_assignment2`` is a user's package of that name
from . import log, util
from .concurrence import Concurrence
from .iterator import Iterator
from .log import set_loggers
from .machine import Container, Sequence, StateMachine
from .states import (CBState, InvalidConstructionError, InvalidStateError,
                     InvalidTransitionError, InvalidUserCodeError, Remapper, SmachError, State,
                     UserData)
from .util import CBInterface, cb_interface, has_smach_interface, set_shutdown_check

# the names whose function changes (set_loggers, set_shutdown_check): read when used
CURRENT = log.NAMES + ('is_shutdown',)

__all__ = [
    'State', 'CBState', 'cb_interface', 'CBInterface', 'has_smach_interface',
    'StateMachine', 'Sequence', 'Concurrence', 'Iterator', 'Container', 'UserData',
    'Remapper', 'SmachError', 'InvalidStateError', 'InvalidTransitionError',
    'InvalidUserCodeError', 'InvalidConstructionError',
    'set_loggers', 'set_shutdown_check',
] + list(CURRENT)


def current(name):
    """The function in use for ``name``, one of :data:`CURRENT`."""
    return util.current_shutdown_check() if name == 'is_shutdown' else log.current(name)


def __getattr__(name):
    if name in CURRENT:
        return current(name)
    raise AttributeError("module %r has no attribute %r" % (__name__, name))


def __dir__():
    return sorted(set(globals()) | set(CURRENT))

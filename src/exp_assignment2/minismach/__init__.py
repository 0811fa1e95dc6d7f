"""A small, SMACH-compatible state machine library.

Debian bookworm ships no ``smach``. The states of this package are written
against the SMACH API, and :mod:`exp_assignment2.smach_api` uses the real
``smach`` when it is importable and this module otherwise. Only the part of
the API the package (and typical SMACH code) uses is provided:

* :class:`State` with outcomes, input/output/io keys and preemption,
* :class:`CBState` and :func:`cb_interface`,
* :class:`StateMachine` (``with sm:`` + :meth:`StateMachine.add`), userdata
  with remapping, start/transition/termination callbacks,
* :class:`Sequence` (states in the order added, joined by a connector
  outcome), :class:`Concurrence` (states at once, an outcome map or
  callback, a child termination callback) and :class:`Iterator` (one state
  once per item),
* the error classes :class:`InvalidStateError`,
  :class:`InvalidTransitionError`, :class:`InvalidUserCodeError`.

The semantics follow SMACH: the first state added is the initial one, an
outcome without a transition is the container's outcome of the same name, a
state returning an outcome it did not register is an
:class:`InvalidTransitionError`, and an exception from user code is wrapped
in :class:`InvalidUserCodeError`.
"""
# relative imports: original_env/shims/smach loads this package by its path
# when ``exp_assignment2`` is a user's package of that name
from .concurrence import Concurrence
from .iterator import Iterator
from .machine import Container, Sequence, StateMachine
from .states import (CBState, InvalidConstructionError, InvalidStateError,
                     InvalidTransitionError, InvalidUserCodeError, Remapper, SmachError, State,
                     UserData, cb_interface)

__all__ = [
    'State', 'CBState', 'cb_interface', 'StateMachine', 'Sequence', 'Concurrence', 'Iterator',
    'Container', 'UserData',
    'Remapper', 'SmachError', 'InvalidStateError', 'InvalidTransitionError',
    'InvalidUserCodeError', 'InvalidConstructionError',
]

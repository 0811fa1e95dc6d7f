"""A small, SMACH-compatible state machine library.

Debian bookworm ships no ``smach``. The states of this package are written
against the SMACH API, and :mod:`exp_assignment2.smach_api` uses the real
``smach`` when it is importable and this module otherwise. Only the part of
the API the package (and typical SMACH code) uses is provided:

* :class:`State` with outcomes, input/output/io keys and preemption,
* :class:`CBState` and :func:`cb_interface`,
* :class:`StateMachine` (``with sm:`` + :meth:`StateMachine.add`), userdata
  with remapping, start/transition/termination callbacks,
* the error classes :class:`InvalidStateError`,
  :class:`InvalidTransitionError`, :class:`InvalidUserCodeError`.

The semantics follow SMACH: the first state added is the initial one, an
outcome without a transition is the container's outcome of the same name, a
state returning an outcome it did not register is an
:class:`InvalidTransitionError`, and an exception from user code is wrapped
in :class:`InvalidUserCodeError`.
"""
import threading
import traceback

__all__ = [
    'State', 'CBState', 'cb_interface', 'StateMachine', 'UserData',
    'Remapper', 'SmachError', 'InvalidStateError', 'InvalidTransitionError',
    'InvalidUserCodeError', 'InvalidConstructionError',
]


class SmachError(Exception):
    """Base class of every error raised by this module."""


class InvalidStateError(SmachError):
    """A state is malformed (e.g. not a State, or its label is taken)."""


class InvalidTransitionError(SmachError):
    """An outcome has no valid target, or a state returned an unknown one."""


class InvalidUserCodeError(SmachError):
    """User code (a state's execute or a callback) raised an exception."""


class InvalidConstructionError(SmachError):
    """A container was used outside of its ``with`` block."""


class UserData(object):
    """Key/value store shared between the states of a container."""

    def __init__(self):
        object.__setattr__(self, '_data', {})

    def keys(self):
        return list(self._data.keys())

    def update(self, other):
        for key in other.keys():
            self._data[key] = other[key]

    def __contains__(self, key):
        return key in self._data

    def __getitem__(self, key):
        return self._data[key]

    def __setitem__(self, key, value):
        self._data[key] = value

    def __getattr__(self, name):
        try:
            return self._data[name]
        except KeyError:
            raise KeyError("SMACH userdata does not contain key '%s'" % name)

    def __setattr__(self, name, value):
        self._data[name] = value


class Remapper(object):
    """A state's view of its container's userdata.

    Only declared keys can be read (input and io keys) or written (output and
    io keys); ``remapping`` maps the state's key names to the container's.
    """

    def __init__(self, ud, input_keys, output_keys, remapping):
        object.__setattr__(self, '_ud', ud)
        object.__setattr__(self, '_input', set(input_keys))
        object.__setattr__(self, '_output', set(output_keys))
        object.__setattr__(self, '_map', dict(remapping))

    def _outer(self, key):
        return self._map.get(key, key)

    def __contains__(self, key):
        return key in self._input and self._outer(key) in self._ud

    def __getitem__(self, key):
        return self.__getattr__(key)

    def __setitem__(self, key, value):
        self.__setattr__(key, value)

    def __getattr__(self, name):
        if name not in self._input:
            raise KeyError("Reading userdata key '%s', but the state declared "
                           "only these input keys: %s" % (name, sorted(self._input)))
        return self._ud[self._outer(name)]

    def __setattr__(self, name, value):
        if name not in self._output:
            raise KeyError("Writing userdata key '%s', but the state declared "
                           "only these output keys: %s" % (name, sorted(self._output)))
        self._ud[self._outer(name)] = value


class State(object):
    """Base class of a state: override :meth:`execute` and return an outcome."""

    def __init__(self, outcomes=(), input_keys=(), output_keys=(), io_keys=()):
        self._outcomes = []
        self._input_keys = set()
        self._output_keys = set()
        self.register_outcomes(outcomes)
        self.register_input_keys(list(input_keys) + list(io_keys))
        self.register_output_keys(list(output_keys) + list(io_keys))
        self._preempt_requested = False

    def execute(self, ud):
        """Run the state; return one of its registered outcomes."""
        raise NotImplementedError('State.execute must be overridden')

    # outcomes and keys
    def register_outcomes(self, outcomes):
        for outcome in outcomes:
            if outcome not in self._outcomes:
                self._outcomes.append(outcome)

    def get_registered_outcomes(self):
        return tuple(self._outcomes)

    def register_io_keys(self, keys):
        self.register_input_keys(keys)
        self.register_output_keys(keys)

    def register_input_keys(self, keys):
        self._input_keys.update(keys)

    def register_output_keys(self, keys):
        self._output_keys.update(keys)

    def get_registered_input_keys(self):
        return tuple(self._input_keys)

    def get_registered_output_keys(self):
        return tuple(self._output_keys)

    # preemption
    def request_preempt(self):
        """Ask the state to stop as soon as it can."""
        self._preempt_requested = True

    def service_preempt(self):
        """Acknowledge a preempt request (the state has stopped)."""
        self._preempt_requested = False

    def recall_preempt(self):
        """Withdraw a preempt request."""
        self._preempt_requested = False

    def preempt_requested(self):
        return self._preempt_requested


def cb_interface(outcomes=(), input_keys=(), output_keys=(), io_keys=()):
    """Decorator declaring the outcomes and keys of a :class:`CBState` callback."""
    def decorate(cb):
        cb._smach_outcomes = list(outcomes)
        cb._smach_input_keys = list(input_keys) + list(io_keys)
        cb._smach_output_keys = list(output_keys) + list(io_keys)
        return cb
    return decorate


class CBState(State):
    """A state that calls ``cb(userdata, *cb_args, **cb_kwargs)``."""

    def __init__(self, cb, cb_args=(), cb_kwargs=None, outcomes=(),
                 input_keys=(), output_keys=(), io_keys=()):
        State.__init__(self, outcomes, input_keys, output_keys, io_keys)
        self._cb = cb
        self._cb_args = list(cb_args)
        self._cb_kwargs = dict(cb_kwargs or {})
        self.register_outcomes(getattr(cb, '_smach_outcomes', ()))
        self.register_input_keys(getattr(cb, '_smach_input_keys', ()))
        self.register_output_keys(getattr(cb, '_smach_output_keys', ()))

    def execute(self, ud):
        return self._cb(ud, *self._cb_args, **self._cb_kwargs)


class StateMachine(State):
    """A container running one state at a time along labelled transitions."""

    _construction_stack = []
    _construction_lock = threading.RLock()

    def __init__(self, outcomes, input_keys=(), output_keys=()):
        State.__init__(self, outcomes, input_keys, output_keys)
        self.userdata = UserData()
        self._states = {}
        self._order = []
        self._transitions = {}
        self._remappings = {}
        self._initial_state_label = None
        self._current_label = None
        self._current_state = None
        self._lock = threading.RLock()
        self._start_cbs = []
        self._transition_cbs = []
        self._termination_cbs = []

    # construction
    def __enter__(self):
        StateMachine._construction_lock.acquire()
        StateMachine._construction_stack.append(self)
        return self

    def __exit__(self, exc_type, exc, tb):
        StateMachine._construction_stack.pop()
        StateMachine._construction_lock.release()
        return False

    @staticmethod
    def add(label, state, transitions=None, remapping=None):
        """Add ``state`` as ``label`` to the container opened with ``with``."""
        if not StateMachine._construction_stack:
            raise InvalidConstructionError(
                'StateMachine.add must be called inside a "with sm:" block')
        sm = StateMachine._construction_stack[-1]
        if not isinstance(state, State):
            raise InvalidStateError("State '%s' is not a State: %r" % (label, state))
        if label in sm._states:
            raise InvalidStateError("A state labelled '%s' already exists" % label)
        if label in sm._outcomes:
            raise InvalidStateError(
                "State label '%s' is also an outcome of its container" % label)
        transitions = dict(transitions or {})
        for outcome in state.get_registered_outcomes():
            transitions.setdefault(outcome, None)
        sm._states[label] = state
        sm._order.append(label)
        sm._transitions[label] = transitions
        sm._remappings[label] = dict(remapping or {})
        if sm._initial_state_label is None:
            sm._initial_state_label = label
        return state

    def set_initial_state(self, initial_states, userdata=None):
        """Start at ``initial_states[0]`` instead of the first state added."""
        self._initial_state_label = initial_states[0]
        if userdata is not None:
            self.userdata.update(userdata)

    def get_children(self):
        return dict(self._states)

    def get_initial_states(self):
        return [self._initial_state_label]

    def get_active_states(self):
        with self._lock:
            return [self._current_label] if self._current_label else []

    def is_running(self):
        return self._current_label is not None

    # callbacks (same signatures as smach: cb(userdata, active_states, *args))
    def register_start_cb(self, cb, cb_args=()):
        self._start_cbs.append((cb, list(cb_args)))

    def register_transition_cb(self, cb, cb_args=()):
        self._transition_cbs.append((cb, list(cb_args)))

    def register_termination_cb(self, cb, cb_args=()):
        self._termination_cbs.append((cb, list(cb_args)))

    def _call_cbs(self, cbs, *args):
        for cb, cb_args in cbs:
            try:
                cb(self.userdata, *(list(args) + cb_args))
            except Exception as exc:
                raise InvalidUserCodeError(
                    'Could not execute callback %r: %s\n%s'
                    % (cb, exc, traceback.format_exc()))

    # preemption reaches the running child
    def request_preempt(self):
        with self._lock:
            State.request_preempt(self)
            if self._current_state is not None:
                self._current_state.request_preempt()

    def check_consistency(self):
        """Raise if a transition leads nowhere or names an unknown outcome."""
        if self._initial_state_label not in self._states:
            raise InvalidTransitionError(
                "Initial state '%s' is not a state of this container"
                % self._initial_state_label)
        for label, transitions in self._transitions.items():
            registered = self._states[label].get_registered_outcomes()
            for outcome, target in transitions.items():
                if outcome not in registered:
                    raise InvalidTransitionError(
                        "State '%s' maps outcome '%s', which it does not register "
                        "(registered: %s)" % (label, outcome, list(registered)))
                final = outcome if target is None else target
                if final not in self._states and final not in self._outcomes:
                    raise InvalidTransitionError(
                        "Outcome '%s' of state '%s' leads to '%s', which is neither "
                        "a state nor an outcome of the container %s"
                        % (outcome, label, final, list(self._outcomes)))

    def execute(self, parent_ud=None):
        """Run from the initial state until a container outcome is reached."""
        self.check_consistency()
        if parent_ud is not None:
            for key in self._input_keys:
                if key in parent_ud:
                    self.userdata[key] = parent_ud[key]
        with self._lock:
            self._current_label = self._initial_state_label
            self._current_state = self._states[self._current_label]
        self._call_cbs(self._start_cbs, [self._current_label])
        outcome = None
        try:
            while outcome is None:
                outcome = self._step()
        finally:
            with self._lock:
                self._current_label = None
                self._current_state = None
            self.service_preempt()
        if parent_ud is not None:
            for key in self._output_keys:
                if key in self.userdata:
                    parent_ud[key] = self.userdata[key]
        self._call_cbs(self._termination_cbs, [], outcome)
        return outcome

    def _step(self):
        """Run the current state once; return the container outcome or None."""
        label, state = self._current_label, self._current_state
        if self.preempt_requested():
            state.request_preempt()
        ud = Remapper(self.userdata, state.get_registered_input_keys(),
                      state.get_registered_output_keys(), self._remappings[label])
        try:
            outcome = state.execute(ud)
        except SmachError:
            raise
        except Exception as exc:
            raise InvalidUserCodeError(
                "Could not execute state '%s' of type %s: %s\n%s"
                % (label, type(state).__name__, exc, traceback.format_exc()))
        if outcome not in state.get_registered_outcomes():
            raise InvalidTransitionError(
                "State '%s' returned outcome '%s', which it did not register "
                "(registered: %s)" % (label, outcome, list(state.get_registered_outcomes())))
        target = self._transitions[label].get(outcome)
        final = outcome if target is None else target
        if final in self._states:
            with self._lock:
                self._current_label = final
                self._current_state = self._states[final]
                if self.preempt_requested():
                    self._current_state.request_preempt()
            self._call_cbs(self._transition_cbs, [final])
            return None
        return final

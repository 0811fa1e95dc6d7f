"""SMACH's StateMachine and Sequence containers (see :mod:`exp_assignment2.minismach`)."""
import threading
import traceback

from . import log, util
from .states import (InvalidConstructionError, InvalidStateError, InvalidTransitionError,
                     InvalidUserCodeError, Remapper, SmachError, State, UserData)


class Container(State):
    """What every container shares: its userdata, children built in a
    ``with container:`` block (``Kind.add`` adds to the innermost one open),
    and start/transition/termination callbacks (``cb(userdata,
    active_states, *args)``, as SMACH calls them)."""

    _construction_stack = []
    _construction_lock = threading.RLock()

    def __init__(self, outcomes, input_keys=(), output_keys=()):
        State.__init__(self, outcomes, input_keys, output_keys)
        self.userdata = UserData()
        self._states = {}
        self._remappings = {}
        self._start_cbs = []
        self._transition_cbs = []
        self._termination_cbs = []

    def __enter__(self):
        Container._construction_lock.acquire()
        Container._construction_stack.append(self)
        return self

    def __exit__(self, exc_type, exc, tb):
        Container._construction_stack.pop()
        Container._construction_lock.release()
        return False

    @classmethod
    def _opened(cls, label, state):
        """The innermost container opened with ``with``, which must be a
        ``cls``, checked for a new child ``state`` labelled ``label``."""
        if not Container._construction_stack:
            raise InvalidConstructionError(
                '%s.add must be called inside a "with container:" block' % cls.__name__)
        container = Container._construction_stack[-1]
        if not isinstance(container, cls):
            raise InvalidConstructionError(
                "%s.add('%s', ...) inside a %s's with block" % (
                    cls.__name__, label, type(container).__name__))
        if not isinstance(state, State):
            raise InvalidStateError("State '%s' is not a State: %r" % (label, state))
        if label in container._states:
            raise InvalidStateError("A state labelled '%s' already exists" % label)
        if label in container._outcomes:
            raise InvalidStateError(
                "State label '%s' is also an outcome of its container" % label)
        return container

    def get_children(self):
        return dict(self._states)

    def __getitem__(self, label):
        return self._states[label]

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

    def _child_view(self, label):
        state = self._states[label]
        return Remapper(self.userdata, state.get_registered_input_keys(),
                        state.get_registered_output_keys(), self._remappings[label])

    def _run_child(self, label):
        """Execute child ``label`` on its view of the userdata; user code's
        exceptions come out as InvalidUserCodeError."""
        state = self._states[label]
        try:
            return state.execute(self._child_view(label))
        except SmachError:
            raise
        except Exception as exc:
            raise InvalidUserCodeError(
                "Could not execute state '%s' of type %s: %s\n%s"
                % (label, type(state).__name__, exc, traceback.format_exc()))

    def _copy_in(self, parent_ud):
        if parent_ud is not None:
            for key in self._input_keys:
                if key in parent_ud:
                    self.userdata[key] = parent_ud[key]

    def _copy_out(self, parent_ud):
        if parent_ud is not None:
            for key in self._output_keys:
                if key in self.userdata:
                    parent_ud[key] = self.userdata[key]


class StateMachine(Container):
    """A container running one state at a time along labelled transitions."""

    def __init__(self, outcomes, input_keys=(), output_keys=()):
        Container.__init__(self, outcomes, input_keys, output_keys)
        self._order = []
        self._transitions = {}
        self._initial_state_label = None
        self._current_label = None
        self._current_state = None
        self._executor = None       # the thread in execute (set_preempt_handler asks)
        self._lock = threading.RLock()

    @staticmethod
    def add(label, state, transitions=None, remapping=None):
        """Add ``state`` as ``label`` to the container opened with ``with``."""
        sm = StateMachine._opened(label, state)
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

    def get_initial_states(self):
        return [self._initial_state_label]

    def get_active_states(self):
        with self._lock:
            return [self._current_label] if self._current_label else []

    def is_running(self):
        return self._current_label is not None

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
        """Run from the initial state until a container outcome is reached;
        None when the shutdown check (smach_ros: rospy's) stopped it first."""
        self.check_consistency()
        self._copy_in(parent_ud)
        with self._lock:
            self._current_label = self._initial_state_label
            self._current_state = self._states[self._current_label]
            self._executor = threading.current_thread()
        log.info("State machine starting in initial state '%s' with userdata: \n\t%s"
                 % (self._current_label, list(self.userdata.keys())))
        self._call_cbs(self._start_cbs, [self._current_label])
        outcome = last = None
        try:
            while outcome is None and not util.shutting_down():
                last = self._current_label
                outcome = self._step()
        finally:
            with self._lock:
                self._current_label = None
                self._current_state = None
                self._executor = None
            self.service_preempt()
        self._copy_out(parent_ud)
        if outcome is not None:     # SMACH's: the last state's label, and the outcome
            self._call_cbs(self._termination_cbs, [last], outcome)
        return outcome

    def _step(self):
        """Run the current state once; return the container outcome or None."""
        label, state = self._current_label, self._current_state
        if self.preempt_requested():
            state.request_preempt()
        outcome = self._run_child(label)
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
            log.info("State machine transitioning '%s':'%s'-->'%s'" % (label, outcome, final))
            self._call_cbs(self._transition_cbs, [final])
            return None
        log.info("State machine terminating '%s':'%s':'%s'" % (label, outcome, final))
        return final


class Sequence(StateMachine):
    """A StateMachine whose states run in the order they are added: each
    one's ``connector_outcome`` leads to the next (the last one's is the
    container's outcome of that name); ``transitions`` add other ways out."""

    def __init__(self, outcomes, connector_outcome, input_keys=(), output_keys=()):
        StateMachine.__init__(self, outcomes, input_keys, output_keys)
        self._connector_outcome = connector_outcome
        self._last_label = None

    @staticmethod
    def add(label, state, transitions=None, remapping=None):
        seq = Sequence._opened(label, state)
        StateMachine.add(label, state, transitions, remapping)
        if seq._last_label is not None:
            seq._transitions[seq._last_label][seq._connector_outcome] = label
        seq._last_label = label
        return state

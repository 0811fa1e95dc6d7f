"""SMACH's Concurrence container (see :mod:`exp_assignment2.minismach`)."""
import threading
import traceback

from . import log, util
from .machine import Container
from .states import InvalidStateError, InvalidTransitionError, InvalidUserCodeError, SmachError

WAIT_STEP = 0.1     # s: the longest wait without a look at the preempt flag


class Concurrence(Container):
    """Runs its states at once, each in a thread, and ends when all have
    ended, or when ``child_termination_cb(outcomes)`` returns True after one
    ended (the others are then preempted and waited for). Its outcome is the
    last entry of ``outcome_map`` ({container outcome: {label: child
    outcome}}) that every child it names matches, else ``default_outcome``;
    ``outcome_cb(outcomes)`` overrides it when it returns one (as SMACH). A
    preempt reaches every running child. ``outcomes`` given to the callbacks:
    {label: outcome, None while running}.
    """

    def __init__(self, outcomes, default_outcome, input_keys=(), output_keys=(),
                 outcome_map=None, outcome_cb=None, child_termination_cb=None):
        Container.__init__(self, outcomes, input_keys, output_keys)
        self._default_outcome = default_outcome
        self._outcome_map = dict(outcome_map or {})
        self._outcome_cb = outcome_cb
        self._child_termination_cb = child_termination_cb
        self._order = []
        self._done = threading.Condition()
        self._child_outcomes = {}

    @staticmethod
    def add(label, state, remapping=None):
        """Add ``state`` as ``label`` to the Concurrence opened with ``with``."""
        cc = Concurrence._opened(label, state)
        cc._states[label] = state
        cc._order.append(label)
        cc._remappings[label] = dict(remapping or {})
        return state

    def get_active_states(self):
        with self._done:
            return [label for label, outcome in self._child_outcomes.items() if outcome is None]

    def get_initial_states(self):
        return list(self._order)

    def check_consistency(self):
        if self._default_outcome not in self._outcomes:
            raise InvalidTransitionError(
                "Default outcome '%s' is not an outcome of the Concurrence %s"
                % (self._default_outcome, list(self._outcomes)))
        for outcome, children in self._outcome_map.items():
            if outcome not in self._outcomes:
                raise InvalidTransitionError(
                    "outcome_map names '%s', which is not an outcome of the Concurrence %s"
                    % (outcome, list(self._outcomes)))
            for label, child_outcome in children.items():
                if label not in self._states:
                    raise InvalidStateError(
                        "outcome_map['%s'] names '%s', which is not a state of the "
                        "Concurrence %s" % (outcome, label, list(self._order)))
                if child_outcome not in self._states[label].get_registered_outcomes():
                    raise InvalidTransitionError(
                        "outcome_map['%s'] expects '%s' from '%s', which does not register it "
                        "(registered: %s)" % (outcome, child_outcome, label,
                                              list(self._states[label].get_registered_outcomes())))

    def request_preempt(self):
        with self._done:
            Container.request_preempt(self)
            for label, outcome in self._child_outcomes.items():
                if outcome is None:
                    self._states[label].request_preempt()
            self._done.notify_all()

    def execute(self, parent_ud=None):
        self.check_consistency()
        self._copy_in(parent_ud)
        errors, ending = [], []
        with self._done:
            self._child_outcomes = {label: None for label in self._order}
        threads = {label: threading.Thread(target=self._child_thread, args=(label, errors, ending),
                                           name='concurrence:' + label, daemon=True)
                   for label in self._order}
        log.info('Concurrence starting with userdata: \n\t%s' % list(self.userdata.keys()))
        self._call_cbs(self._start_cbs, list(self._order))
        for thread in threads.values():
            thread.start()
        with self._done:
            while not (ending or errors or self.preempt_requested()):
                self._done.wait(WAIT_STEP)
            for label, outcome in self._child_outcomes.items():
                if outcome is None:
                    self._states[label].request_preempt()
        for thread in threads.values():     # as SMACH: no longer once shutting down
            while thread.is_alive() and not util.shutting_down():
                thread.join(WAIT_STEP)
        outcomes = dict(self._child_outcomes)
        log.info('Concurrent Outcomes: %s' % outcomes)
        if errors:
            raise errors[0]
        if self.preempt_requested():
            self.service_preempt()
        outcome = self._outcome(outcomes)
        self._copy_out(parent_ud)
        self._call_cbs(self._termination_cbs, list(self._order), outcome)
        return outcome

    def _child_thread(self, label, errors, ending):
        state = self._states[label]
        try:
            outcome = state.execute(self._child_view(label))
            if outcome not in state.get_registered_outcomes():
                raise InvalidTransitionError(
                    "State '%s' returned outcome '%s', which it did not register "
                    "(registered: %s)" % (label, outcome, list(state.get_registered_outcomes())))
        except SmachError as exc:
            outcome, error = None, exc
        except BaseException as exc:          # SystemExit too: the container must hear of it
            outcome, error = None, InvalidUserCodeError(
                "Could not execute state '%s' of type %s: %s\n%s"
                % (label, type(state).__name__, exc, traceback.format_exc()))
        with self._done:
            if outcome is None:
                errors.append(error)
            else:
                self._child_outcomes[label] = outcome
                state.service_preempt()
                if all(o is not None for o in self._child_outcomes.values()):
                    ending.append(label)
                if self._child_termination_cb is not None:
                    try:
                        if self._child_termination_cb(dict(self._child_outcomes)):
                            ending.append(label)
                    except Exception as exc:
                        errors.append(InvalidUserCodeError(
                            'Could not execute child termination callback %r: %s\n%s'
                            % (self._child_termination_cb, exc, traceback.format_exc())))
            self._done.notify_all()

    def _outcome(self, outcomes):
        chosen = self._default_outcome
        for outcome, children in self._outcome_map.items():
            if all(outcomes[label] == expected for label, expected in children.items()):
                chosen = outcome
        if self._outcome_cb is not None:
            try:
                outcome = self._outcome_cb(dict(outcomes))
            except Exception as exc:
                raise InvalidUserCodeError('Could not execute outcome callback %r: %s\n%s'
                                           % (self._outcome_cb, exc, traceback.format_exc()))
            if outcome is not None and outcome not in self._outcomes:
                raise InvalidTransitionError(
                    "The outcome callback returned '%s', which is not an outcome of the "
                    "Concurrence %s" % (outcome, list(self._outcomes)))
            chosen = outcome or chosen
        return chosen

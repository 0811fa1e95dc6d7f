"""SMACH's Iterator container (see :mod:`exp_assignment2.minismach`)."""
from . import log, util
from .machine import Container
from .states import InvalidStateError


class Iterator(Container):
    """Runs one contained state once per item of ``it`` (an iterable, or a
    callable giving one), the item in userdata ``it_label``. After a run it
    goes on to the next item while the outcome is one of ``loop_outcomes``
    (any outcome when there are none) and not one of ``break_outcomes``;
    otherwise, or on a preempt, that outcome ends it. When the items run out
    the outcome is ``exhausted_outcome``. ``final_outcome_map`` renames the
    final outcome, as SMACH's."""

    def __init__(self, outcomes, input_keys=(), output_keys=(), it=(), it_label='it_data',
                 exhausted_outcome='exhausted'):
        Container.__init__(self, outcomes, input_keys, output_keys)
        self._items, self._items_label = it, it_label
        self._exhausted_outcome = exhausted_outcome
        self._state_label = None
        self._loop_outcomes, self._break_outcomes, self._final_outcome_map = [], [], {}

    @staticmethod
    def set_iteritems(it, it_label='it_data'):
        """The items of the Iterator opened with ``with``."""
        iterator = Iterator._current()
        iterator._items, iterator._items_label = it, it_label

    @staticmethod
    def set_contained_state(label, state, loop_outcomes=(), break_outcomes=(),
                            final_outcome_map=None):
        """The one state of the Iterator opened with ``with``."""
        iterator = Iterator._opened(label, state)
        if iterator._state_label is not None:
            raise InvalidStateError("Iterator already contains '%s'" % iterator._state_label)
        iterator._states[label], iterator._remappings[label] = state, {}
        iterator._state_label = label
        iterator._loop_outcomes = list(loop_outcomes)
        iterator._break_outcomes = list(break_outcomes)
        iterator._final_outcome_map = dict(final_outcome_map or {})
        return state

    @staticmethod
    def _current():
        if not Container._construction_stack or not isinstance(
                Container._construction_stack[-1], Iterator):
            raise InvalidStateError('Iterator.set_iteritems must be called inside a '
                                    '"with iterator:" block')
        return Container._construction_stack[-1]

    def get_active_states(self):
        return [self._state_label] if self._state_label and self.is_running else []

    is_running = False

    def request_preempt(self):
        Container.request_preempt(self)
        if self._state_label is not None:
            self._states[self._state_label].request_preempt()

    def execute(self, parent_ud=None):
        if self._state_label is None:
            raise InvalidStateError('Iterator has no contained state (set_contained_state)')
        label = self._state_label
        self._copy_in(parent_ud)
        self.is_running = True
        self._call_cbs(self._start_cbs, [label])
        items = self._items() if callable(self._items) else self._items
        outcome = self._exhausted_outcome
        try:
            for item in items:
                if util.shutting_down():        # as SMACH: the last outcome stands
                    break
                log.info('Iterating %s of %s' % (item, self._items))
                self.userdata[self._items_label] = item
                outcome = self._run_child(label)
                if (self.preempt_requested() or outcome in self._break_outcomes
                        or (self._loop_outcomes and outcome not in self._loop_outcomes)):
                    self.service_preempt()
                    break
                self._call_cbs(self._transition_cbs, [label])
            else:
                outcome = self._exhausted_outcome
        finally:
            self.is_running = False
        outcome = self._final_outcome_map.get(outcome, outcome)
        self._copy_out(parent_ud)
        self._call_cbs(self._termination_cbs, [label], outcome)
        return outcome

"""The SMACH-compatible module keeps SMACH's semantics (no ROS needed)."""
import threading

import pytest

from exp_assignment2 import minismach as smach
from exp_assignment2 import smach_api
from minismach_helpers import Returns


class Counter(smach.State):
    """Adds one to ``n`` and says 'again' until it reaches ``limit``."""

    def __init__(self, limit):
        smach.State.__init__(self, outcomes=['again', 'done'], io_keys=['n'])
        self.limit = limit

    def execute(self, ud):
        ud.n = ud.n + 1
        return 'done' if ud.n >= self.limit else 'again'


def test_first_state_added_is_initial_and_transitions_are_followed():
    first, second = Returns('a'), Returns('b')
    sm = smach.StateMachine(outcomes=['end'])
    with sm:
        smach.StateMachine.add('FIRST', first, transitions={'a': 'SECOND', 'b': 'end'})
        smach.StateMachine.add('SECOND', second, transitions={'a': 'FIRST', 'b': 'end'})
    assert sm.execute() == 'end'
    assert (first.runs, second.runs) == (1, 1)


def test_outcome_without_transition_falls_through_to_container_outcome():
    sm = smach.StateMachine(outcomes=['a', 'b', 'other'])
    with sm:
        smach.StateMachine.add('ONLY', Returns('b'))
    assert sm.execute() == 'b'


def test_userdata_loops_with_io_keys():
    sm = smach.StateMachine(outcomes=['done'])
    sm.userdata.n = 0
    with sm:
        smach.StateMachine.add('COUNT', Counter(5), transitions={'again': 'COUNT'})
    assert sm.execute() == 'done'
    assert sm.userdata.n == 5


def test_remapping_maps_state_keys_to_container_keys():
    sm = smach.StateMachine(outcomes=['done'])
    sm.userdata.total = 3
    with sm:
        smach.StateMachine.add('COUNT', Counter(4), transitions={'again': 'COUNT'},
                               remapping={'n': 'total'})
    sm.execute()
    assert sm.userdata.total == 4


def test_undeclared_key_access_is_a_user_code_error():
    class Sneaky(smach.State):
        def __init__(self):
            smach.State.__init__(self, outcomes=['x'])

        def execute(self, ud):
            return ud.secret

    sm = smach.StateMachine(outcomes=['x'])
    sm.userdata.secret = 'x'
    with sm:
        smach.StateMachine.add('S', Sneaky())
    with pytest.raises(smach.InvalidUserCodeError, match='secret'):
        sm.execute()


def test_returning_an_unregistered_outcome_is_an_invalid_transition():
    sm = smach.StateMachine(outcomes=['a', 'b'])
    with sm:
        smach.StateMachine.add('S', Returns('zzz'))
    with pytest.raises(smach.InvalidTransitionError, match='zzz'):
        sm.execute()


def test_mapping_an_unregistered_outcome_is_an_invalid_transition():
    sm = smach.StateMachine(outcomes=['a', 'b'])
    with sm:
        smach.StateMachine.add('S', Returns('a'), transitions={'nope': 'a'})
    with pytest.raises(smach.InvalidTransitionError, match='nope'):
        sm.execute()


def test_unregistered_fall_through_outcome_is_an_invalid_transition():
    sm = smach.StateMachine(outcomes=['b'])
    with sm:
        smach.StateMachine.add('S', Returns('b'))   # 'a' has nowhere to go
    with pytest.raises(smach.InvalidTransitionError, match="'a'"):
        sm.execute()


def test_transition_to_unknown_target_is_an_invalid_transition():
    sm = smach.StateMachine(outcomes=['end'])
    with sm:
        smach.StateMachine.add('S', Returns('a'), transitions={'a': 'NOWHERE', 'b': 'end'})
    with pytest.raises(smach.InvalidTransitionError, match='NOWHERE'):
        sm.execute()


def test_exception_in_user_code_is_wrapped():
    class Broken(smach.State):
        def __init__(self):
            smach.State.__init__(self, outcomes=['x'])

        def execute(self, ud):
            raise RuntimeError('boom')

    sm = smach.StateMachine(outcomes=['x'])
    with sm:
        smach.StateMachine.add('B', Broken())
    with pytest.raises(smach.InvalidUserCodeError, match='boom'):
        sm.execute()


def test_add_outside_with_block_and_bad_states_are_rejected():
    with pytest.raises(smach.InvalidConstructionError):
        smach.StateMachine.add('S', Returns('a'))
    sm = smach.StateMachine(outcomes=['a'])
    with sm:
        with pytest.raises(smach.InvalidStateError):
            smach.StateMachine.add('S', object())
        smach.StateMachine.add('S', Returns('a'))
        with pytest.raises(smach.InvalidStateError):
            smach.StateMachine.add('S', Returns('a'))


def test_cbstate_and_cb_interface():
    @smach.cb_interface(outcomes=['even', 'odd'], input_keys=['value'])
    def parity(ud, offset):
        return 'even' if (ud.value + offset) % 2 == 0 else 'odd'

    sm = smach.StateMachine(outcomes=['even', 'odd'])
    sm.userdata.value = 3
    with sm:
        smach.StateMachine.add('P', smach.CBState(parity, cb_args=[1]))
    assert sm.execute() == 'even'


def test_preempt_request_service_and_recall():
    state = Returns('a')
    assert not state.preempt_requested()
    state.request_preempt()
    assert state.preempt_requested()
    state.service_preempt()
    assert not state.preempt_requested()
    state.request_preempt()
    state.recall_preempt()
    assert not state.preempt_requested()


def test_preempting_the_machine_reaches_the_running_state():
    started = threading.Event()

    class Waiter(smach.State):
        def __init__(self):
            smach.State.__init__(self, outcomes=['preempted'])

        def execute(self, ud):
            started.set()
            while not self.preempt_requested():
                threading.Event().wait(0.001)
            self.service_preempt()
            return 'preempted'

    sm = smach.StateMachine(outcomes=['preempted'])
    with sm:
        smach.StateMachine.add('WAIT', Waiter())
    result = []
    worker = threading.Thread(target=lambda: result.append(sm.execute()))
    worker.start()
    assert started.wait(2.0)
    sm.request_preempt()
    worker.join(2.0)
    assert result == ['preempted']
    assert not sm.preempt_requested()


def test_active_state_is_reported_on_start_and_every_transition():
    seen = []
    sm = smach.StateMachine(outcomes=['end'])
    sm.userdata.n = 0
    with sm:
        smach.StateMachine.add('A', Returns('a'), transitions={'a': 'COUNT', 'b': 'end'})
        smach.StateMachine.add('COUNT', Counter(2), transitions={'again': 'COUNT', 'done': 'end'})
    smach_api.report_active_state(sm, seen.append)
    assert sm.execute() == 'end'
    assert seen == ['A', 'COUNT', 'COUNT']
    assert sm.get_active_states() == []


def test_nested_container_passes_userdata_through():
    inner = smach.StateMachine(outcomes=['done'], input_keys=['n'], output_keys=['n'])
    with inner:
        smach.StateMachine.add('COUNT', Counter(3), transitions={'again': 'COUNT'})
    outer = smach.StateMachine(outcomes=['finished'])
    outer.userdata.n = 0
    with outer:
        smach.StateMachine.add('INNER', inner, transitions={'done': 'finished'})
    assert outer.execute() == 'finished'
    assert outer.userdata.n == 3


def test_smach_api_prefers_real_smach_and_never_shadows_it():
    try:
        import smach as real  # noqa: F401
        assert smach_api.IS_REAL_SMACH
    except ImportError:
        assert smach_api.smach is smach
        assert not smach_api.IS_REAL_SMACH

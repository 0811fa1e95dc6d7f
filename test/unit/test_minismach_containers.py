"""minismach's other containers keep SMACH's semantics: Sequence,
Concurrence and Iterator (no ROS needed)."""
import threading

import pytest

from exp_assignment2 import minismach as smach
from minismach_helpers import Returns


class Waits(smach.State):
    """Waits until preempted ('preempted') or released ('done')."""

    def __init__(self):
        smach.State.__init__(self, outcomes=['done', 'preempted'])
        self.release, self.started = threading.Event(), threading.Event()

    def execute(self, ud):
        self.started.set()
        while not self.release.wait(0.01):
            if self.preempt_requested():
                self.service_preempt()
                return 'preempted'
        return 'done'


class Writes(smach.State):
    def __init__(self, key, value, outcome='done'):
        smach.State.__init__(self, outcomes=['done', 'failed'], output_keys=[key])
        self.key, self.value, self.outcome = key, value, outcome

    def execute(self, ud):
        ud[self.key] = self.value
        return self.outcome


def test_a_sequence_runs_its_states_in_order_along_the_connector():
    order = []

    @smach.cb_interface(outcomes=['next', 'stop'])
    def step(ud, name):
        order.append(name)
        return 'stop' if name == 'halt' else 'next'
    seq = smach.Sequence(outcomes=['next', 'stop'], connector_outcome='next')
    with seq:
        for name in ('a', 'b', 'c'):
            smach.Sequence.add(name.upper(), smach.CBState(step, cb_args=[name]))
    assert seq.execute() == 'next' and order == ['a', 'b', 'c']
    order[:] = []
    seq = smach.Sequence(outcomes=['next', 'stop', 'stopped'], connector_outcome='next')
    with seq:
        smach.Sequence.add('A', smach.CBState(step, cb_args=['a']))
        smach.Sequence.add('HALT', smach.CBState(step, cb_args=['halt']),
                           transitions={'stop': 'stopped'})
        smach.Sequence.add('C', smach.CBState(step, cb_args=['c']))
    assert seq.execute() == 'stopped' and order == ['a', 'halt']


def test_a_concurrence_runs_its_states_at_once_and_maps_their_outcomes():
    waiting, writes = Waits(), Writes('seen', 42)
    cc = smach.Concurrence(outcomes=['both', 'other'], default_outcome='other',
                           output_keys=['seen'],
                           outcome_map={'both': {'WAIT': 'done', 'WRITE': 'done'}})
    with cc:
        smach.Concurrence.add('WAIT', waiting)
        smach.Concurrence.add('WRITE', writes, remapping={'seen': 'seen'})
    parent = smach.UserData()
    threading.Timer(0.1, waiting.release.set).start()
    assert cc.execute(parent) == 'both'
    assert parent.seen == 42
    writes.outcome = 'failed'
    waiting.release.clear()
    threading.Timer(0.1, waiting.release.set).start()
    assert cc.execute(parent) == 'other'                # no entry matched: the default


def test_a_child_termination_callback_preempts_the_others():
    waiting = Waits()
    ended = []

    def one_is_enough(outcomes):
        ended.append(dict(outcomes))
        return outcomes['QUICK'] is not None
    cc = smach.Concurrence(outcomes=['quick', 'slow'], default_outcome='slow',
                           child_termination_cb=one_is_enough,
                           outcome_cb=lambda o: 'quick' if o['WAIT'] == 'preempted' else None)
    with cc:
        smach.Concurrence.add('WAIT', waiting)
        smach.Concurrence.add('QUICK', Returns('a'))
    assert cc.execute() == 'quick'
    assert ended[0] == {'WAIT': None, 'QUICK': 'a'}
    assert not waiting.preempt_requested()              # serviced


def test_a_preempt_reaches_every_running_child_of_a_concurrence_in_a_state_machine():
    first, second = Waits(), Waits()
    sm = smach.StateMachine(outcomes=['stopped', 'done'])
    with sm:
        cc = smach.Concurrence(outcomes=['stopped', 'done'], default_outcome='done',
                               outcome_map={'stopped': {'ONE': 'preempted', 'TWO': 'preempted'}})
        smach.StateMachine.add('BOTH', cc, transitions={'stopped': 'stopped', 'done': 'done'})
        with cc:
            smach.Concurrence.add('ONE', first)
            smach.Concurrence.add('TWO', second)
        with pytest.raises(smach.InvalidConstructionError):
            smach.Concurrence.add('THREE', Waits())     # the innermost open is the machine
    result = []
    runner = threading.Thread(target=lambda: result.append(sm.execute()))
    runner.start()
    assert first.started.wait(2.0) and second.started.wait(2.0)
    assert sorted(cc.get_active_states()) == ['ONE', 'TWO']
    sm.request_preempt()
    runner.join(2.0)
    assert result == ['stopped']


def test_a_concurrence_names_what_is_wrong():
    cc = smach.Concurrence(outcomes=['a'], default_outcome='a',
                           outcome_map={'a': {'NOPE': 'done'}})
    with cc:
        smach.Concurrence.add('ONE', Returns('a'))
    with pytest.raises(smach.InvalidStateError, match="'NOPE', which is not a state"):
        cc.execute()
    cc = smach.Concurrence(outcomes=['a'], default_outcome='a')
    with cc:
        smach.Concurrence.add('BAD', smach.CBState(lambda ud: 1 / 0, outcomes=['x']))
    with pytest.raises(smach.InvalidUserCodeError, match="state 'BAD'.*division by zero"):
        cc.execute()

    def leave(ud):
        raise SystemExit(3)
    cc = smach.Concurrence(outcomes=['a'], default_outcome='a')
    with cc:
        smach.Concurrence.add('EXIT', smach.CBState(leave, outcomes=['x']))
        smach.Concurrence.add('WAIT', Waits())
    with pytest.raises(smach.InvalidUserCodeError, match="state 'EXIT'"):
        cc.execute()                                    # not a wait for ever


def test_an_outcome_callback_that_says_nothing_leaves_the_mapped_outcome():
    cc = smach.Concurrence(outcomes=['mapped', 'default'], default_outcome='default',
                           outcome_map={'mapped': {'ONE': 'a'}}, outcome_cb=lambda o: None)
    with cc:
        smach.Concurrence.add('ONE', Returns('a'))
    assert cc.execute() == 'mapped'


def test_an_iterator_runs_its_state_per_item_until_a_break_or_the_end():
    seen = []

    @smach.cb_interface(input_keys=['item'], outcomes=['next', 'found'])
    def look(ud):
        seen.append(ud.item)
        return 'found' if ud.item == 'ball' else 'next'
    it = smach.Iterator(outcomes=['found_it', 'none'], it=['grass', 'ball', 'kennel'],
                        it_label='item', exhausted_outcome='none')
    with it:
        smach.Iterator.set_contained_state('LOOK', smach.CBState(look), loop_outcomes=['next'],
                                           final_outcome_map={'found': 'found_it'})
    assert it.execute() == 'found_it' and seen == ['grass', 'ball']
    seen[:] = []
    with it:
        smach.Iterator.set_iteritems(lambda: iter(['grass', 'kennel']), 'item')
    assert it.execute() == 'none' and seen == ['grass', 'kennel']

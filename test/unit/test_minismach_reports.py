"""minismach's smach.log and smach.util: where a machine's reports go, the shutdown
check, callback interfaces (no ROS needed; smach_ros' use of them is in
test_smach_ros_glue.py)."""
import threading

import pytest

from exp_assignment2 import minismach as smach
from minismach_helpers import Returns


@pytest.fixture
def heard():
    """{'info': [...], 'warn': [...], 'debug': [...], 'error': [...]} of what SMACH
    reported through set_loggers; the loggers and shutdown check restored after."""
    before = {name: smach.current(name) for name in smach.CURRENT}
    said = {kind: [] for kind in ('info', 'warn', 'debug', 'error')}
    smach.set_loggers(*(said[kind].append for kind in ('info', 'warn', 'debug', 'error')))
    yield said
    smach.set_loggers(*(before[name] for name in ('loginfo', 'logwarn', 'logdebug', 'logerr')))
    smach.set_shutdown_check(before['is_shutdown'])


def two_states():
    sm = smach.StateMachine(outcomes=['end'])
    with sm:
        smach.StateMachine.add('A', Returns('a', outcomes=['a']), transitions={'a': 'B'})
        smach.StateMachine.add('B', Returns('b', outcomes=['b']), transitions={'b': 'end'})
    return sm


def test_set_loggers_takes_what_a_machine_reports_in_smachs_order(heard):
    assert two_states().execute() == 'end'
    assert heard['info'] == ["State machine starting in initial state 'A' with userdata: \n\t[]",
                             "State machine transitioning 'A':'a'-->'B'",
                             "State machine terminating 'B':'b':'end'"]
    assert heard['warn'] == heard['debug'] == heard['error'] == []


def test_the_log_functions_are_the_ones_in_use(heard):
    assert [smach.loginfo, smach.logwarn, smach.logdebug, smach.logerr] == [
        heard[kind].append for kind in ('info', 'warn', 'debug', 'error')]
    smach.loginfo('i')
    smach.logwarn('w')
    smach.logdebug('d')
    smach.logerr('e')
    assert [heard[kind] for kind in ('info', 'warn', 'debug', 'error')] == [
        ['i'], ['w'], ['d'], ['e']]


def test_the_default_loggers_print_as_smachs(capsys):
    smach.log.loginfo('x')
    smach.log.logwarn('y')
    smach.log.logdebug('z')
    smach.log.logerr(3)
    assert capsys.readouterr().out.splitlines() == [
        '[  INFO ] : x', '[  WARN ] : y', '[ DEBUG ] : z', '[ ERROR ] : 3']


def test_an_error_is_logged_when_it_is_made(heard):
    sm = smach.StateMachine(outcomes=['a'])
    with sm:
        smach.StateMachine.add('BROKEN', smach.CBState(lambda ud: {}['sensor'], outcomes=['a']))
    with pytest.raises(smach.InvalidUserCodeError):
        sm.execute()
    assert len(heard['error']) == 1
    assert heard['error'][0].startswith("InvalidUserCodeError: Could not execute state 'BROKEN'")
    assert "KeyError: 'sensor'" in heard['error'][0]


class Stepper(smach.State):
    """Says 'again' forever; the test's shutdown flag goes up at its third run."""

    def __init__(self, flag):
        smach.State.__init__(self, outcomes=['again'])
        self.flag, self.runs = flag, 0

    def execute(self, ud):
        self.runs += 1
        if self.runs == 3:
            self.flag.set()
        return 'again'


def test_set_shutdown_check_stops_a_machine_after_its_state(heard):
    flag = threading.Event()
    smach.set_shutdown_check(flag.is_set)
    assert smach.is_shutdown == flag.is_set and not smach.is_shutdown()
    ended = []
    sm = smach.StateMachine(outcomes=['end'])
    sm.register_termination_cb(lambda *args: ended.append(args))
    state = Stepper(flag)
    with sm:
        smach.StateMachine.add('LOOP', state, transitions={'again': 'LOOP'})
    assert sm.execute() is None             # SMACH's: no outcome, no termination callback
    assert state.runs == 3 and ended == [] and not sm.is_running()
    assert smach.is_shutdown()


def test_the_shutdown_check_stops_an_iterator_and_a_concurrences_wait(heard):
    flag = threading.Event()
    smach.set_shutdown_check(flag.is_set)
    it = smach.Iterator(outcomes=['again', 'done'], it=range(10), exhausted_outcome='done')
    state = Stepper(flag)
    with it:
        smach.Iterator.set_contained_state('STEP', state, loop_outcomes=['again'])
    assert it.execute() == 'again' and state.runs == 3     # the last outcome stands

    class Stubborn(smach.State):     # ignores the preempt the Concurrence sends
        def __init__(self):
            smach.State.__init__(self, outcomes=['done'])
            self.release = threading.Event()

        def execute(self, ud):
            self.release.wait(10)
            return 'done'

    stubborn = Stubborn()
    cc = smach.Concurrence(outcomes=['over'], default_outcome='over',
                           child_termination_cb=lambda outcomes: True)
    with cc:
        smach.Concurrence.add('QUICK', Returns('a', outcomes=['a']))
        smach.Concurrence.add('STUBBORN', stubborn)
    try:
        assert cc.execute() == 'over'     # did not wait for STUBBORN: shutting down
        assert heard['info'][-1] == "Concurrent Outcomes: {'QUICK': 'a', 'STUBBORN': None}"
    finally:
        stubborn.release.set()


def test_cb_interface_makes_a_cbinterface_a_cbstate_registers():
    @smach.cb_interface(outcomes=['big', 'small'], input_keys=['n'], output_keys=['seen'])
    def size(ud, limit):
        ud.seen = ud.n
        return 'big' if ud.n > limit else 'small'

    assert isinstance(size, smach.CBInterface) and smach.has_smach_interface(size)
    assert size.get_registered_outcomes() == ('big', 'small')
    assert size.get_registered_input_keys() == ('n',)
    assert size.get_registered_output_keys() == ('seen',)
    state = smach.CBState(size, cb_args=[5])
    assert set(state.get_registered_outcomes()) == {'big', 'small'}
    sm = smach.StateMachine(outcomes=['big', 'small'])
    sm.userdata.n = 7
    with sm:
        smach.StateMachine.add('SIZE', state)
    assert sm.execute() == 'big' and sm.userdata.seen == 7


def test_a_cbinterface_made_directly_calls_its_callback():
    wrapped = smach.CBInterface(lambda a, b=0: a + b, outcomes=['x'], io_keys=['k'])
    assert wrapped(1, b=2) == 3
    assert wrapped.get_registered_input_keys() == wrapped.get_registered_output_keys() == ('k',)


def test_has_smach_interface_tells_states_and_interfaces_from_plain_callables():
    assert smach.has_smach_interface(Returns('a'))
    assert smach.has_smach_interface(smach.StateMachine(outcomes=['a']))
    assert not smach.has_smach_interface(lambda ud: 'a')


def test_every_container_is_a_container():
    for kind in (smach.StateMachine, smach.Sequence, smach.Concurrence, smach.Iterator):
        assert issubclass(kind, smach.Container) and issubclass(kind, smach.State)
    assert issubclass(smach.InvalidUserCodeError, smach.SmachError)

"""The verdict's rules (exp_assignment2.grading.judge.verdicts.RULES), each alone on
hand-made facts (a Seen), then their order: the precedence docs/grading.md states;
then roslaunch's rules: a node that dies ends nothing unless it is required, and
a system that ended is crashed only when its checks were not met by then."""
import pytest

from exp_assignment2.grading.judge import verdicts
from exp_assignment2.grading.judge.verdicts import RULES, Seen, decide

PASSED = [{'name': 'reaches the ball', 'passed': True}]
FAILED = [{'name': 'reaches the ball', 'passed': False}, {'name': 'head', 'passed': True}]
SIM = {'node': 'gazebo-1', 'code': 1, 'cmd': '/r/scripts/simulator.py x', 'log': 'l'}
DOG = {'node': 'dog-5', 'code': 1, 'cmd': '/w/dog.py', 'log': 'logs/command-0.log',
       'abort': ''}
QT = {'node': 'viewer-3', 'code': -6, 'cmd': '/w/viewer.py', 'log': 'logs/command-0.log',
      'abort': 'qt.qpa.xcb: could not connect to display\nThis application failed'}
REQUIRED = dict(DOG, required=True)
RSP = {'node': 'robot_state_publisher-3', 'code': 1, 'cmd': '/usr/lib/r/robot_state_publisher',
       'log': 'logs/command-0.log', 'abort': '', 'deaths': 4, 'restarted': 3, 'required': False}
TIRED = {'source': 'logs/command-0.log', 'line': 2, 'summary': 'RuntimeError: the dog is tired'}
RUNNING = dict(states=300, sim_time=30.0, duration=30.0, checks=PASSED)
# the system ended by itself at 4 of 30 s, the ball not reached
ENDED = dict(states=40, sim_time=6.0, ended_at=4.0, duration=30.0, checks=FAILED)
MISSING = {'command': 'roslaunch p a.launch', 'log': 'logs/command-0.log',
           'line': 'ERROR: cannot launch node of type [p/ghost.py]: Cannot locate node'}

FAULT = {'what': 'failed while running it', 'error': 'ZeroDivisionError: division by zero '
                                                    '(runner.py:12)'}
# a record's own end (seen.TOLD): nothing of the run was seen
TOLD = dict(built=False, build_rc=None, ended_by='not_run', sandbox_exit=None)

# one case per rule, in the table's order: (rule name, facts, verdict, reason)
CASES = [
    ('refused', dict(TOLD, refused="grading.yaml: submissions: ann: unknown key 'skipp'"),
     'grader_error', "grading.yaml: submissions: ann: unknown key 'skipp'"),
    ('lost', dict(TOLD, lost='Attempted to run task grade-ann on 4 different workers'),
     'grader_error', 'the grader lost this run: Attempted to run task grade-ann on 4 different '
                     'workers'),
    ("a fault of the grader's", dict(RUNNING, grader_fault=FAULT),
     'grader_error', "the grader failed while running it (a fault of the grader's, not the "
                     "student's): ZeroDivisionError: division by zero (runner.py:12)"),
    ('cannot be taken', dict(TOLD, rejected='the submission: no package.xml in it'),
     'not_built', 'the submission: no package.xml in it'),
    ('no sandbox', dict(TOLD, sandbox_error='bwrap: cannot make the cgroup'),
     'grader_error', 'bwrap: cannot make the cgroup'),
    ('no display', dict(built=False, build_rc=None, ended_by='driver_exit',
                        display_error='Xvfb could not start: No such file or directory'),
     'grader_error', "the run's display could not be made: Xvfb could not start: No such "
                     'file or directory'),
    ('sandbox did not start', dict(built=False, build_rc=None, ended_by='driver_exit',
                                   sandbox_exit=1, build_log_line='bwrap: no permission'),
     'grader_error', 'the sandbox did not start (exit 1): bwrap: no permission'),
    ('simulator died', dict(RUNNING, died=[SIM]),
     'grader_error', 'the simulator died (gazebo-1, exit code 1)'),
    ('build failed', dict(build_rc=1, build_error={'file': 'src/counter.cpp', 'line': 3,
                                                   'message': "expected ';'"}),
     'not_built', "src/counter.cpp:3: expected ';'"),
    ('a command started nothing', dict(started_nothing=[('roslaunch p b.launch',
                                                         'RLException: no b.launch')]),
     'not_started', 'roslaunch p b.launch: RLException: no b.launch'),
    ('nothing ran, a node could not launch', dict(launch_errors=[MISSING]),
     'not_started', 'roslaunch p a.launch: ERROR: cannot launch node of type [p/ghost.py]: '
                    'Cannot locate node'),
    ("the grader's processes killed from inside", dict(ENDED, driver_ended=False,
                                                       ended_by='driver_exit', sandbox_exit=-9),
     'crashed', "the run's processes were killed from inside its sandbox: the grader's "
                'driver there got a signal it was not sent by the grader (exit -9)'),
    ('memory limit', dict(ENDED, oom=True, memory_limit_mb=3000),
     'crashed', 'the run used more than its 3000 MB of memory'),
    ('disk limit', dict(ENDED, ended_by='disk_limit'),
     'crashed', 'the run wrote more than its disk limit'),
    ('a required node died', dict(ENDED, ended_by='required_node_died', died=[REQUIRED],
                                  errors=[TIRED]),
     'crashed', 'dog-5 died (exit code 1): RuntimeError: the dog is tired; it was '
                'required="true": roslaunch shut its launch down at 4 of 30 simulated s'),
    ('every command ended', dict(ENDED, ended_by='all_exited', died=[QT]),
     'crashed', 'every command had ended at 4 of 30 simulated s (viewer-3 died (exit code -6 '
                '(SIGABRT)): qt.qpa.xcb: could not connect to display)'),
    ('no ground truth', dict(ended_by='no_simulator'),
     'grader_error', 'the simulator never reported its ground truth'),
    ('starved beside other runs', dict(ENDED, ended_by='starved'),
     'grader_error', 'this machine could not keep it at real time beside other runs: ended at '
                     '4 of 30 simulated s to be run again alone, and it was not (the grading '
                     'was stopped)'),
    ('build limit', dict(built=False, build_rc=None, ended_by='build_limit'),
     'timed_out', 'the build ran past its limit'),
    ('wall-clock limit', dict(RUNNING, sim_time=12.4, duration=60.0, ended_by='wall_limit'),
     'timed_out', '12 of 60 simulated s within the wall-clock limit'),
    ('a check failed', dict(RUNNING, checks=FAILED, died=[DOG], errors=[TIRED]), 'failed_checks',
     'failed: reaches the ball; dog-5 died (exit code 1): RuntimeError: the dog is tired'),
    ('every check that could be run passed', dict(RUNNING), 'passed', ''),
]


def test_every_rule_has_its_case_in_the_tables_order():
    assert [c[0] for c in CASES] == [r.name for r in RULES]
    assert {r.verdict for r in RULES} == set(verdicts.VERDICTS)


@pytest.mark.parametrize('name,facts,verdict,reason', CASES, ids=[c[0] for c in CASES])
def test_each_rule_alone(name, facts, verdict, reason):
    rule = next(r for r in RULES if r.name == name)
    seen = Seen(**facts)
    assert rule.holds(seen)
    assert (rule.verdict, rule.reason(seen)) == (verdict, reason)
    # and it is the first that holds: no earlier rule takes these facts
    assert decide(seen) == (verdict, reason)


def test_a_node_that_dies_is_noted_and_the_run_is_judged_by_its_checks():
    """roslaunch runs on without it: passed when the checks are met, the death said."""
    assert decide(Seen(died=[QT], **RUNNING)) == (
        'passed', 'viewer-3 died (exit code -6 (SIGABRT)): qt.qpa.xcb: could not connect to '
                  'display')
    # a node roslaunch restarted (respawn="true"): once, with how often
    assert decide(Seen(died=[RSP], **RUNNING)) == (
        'passed', 'robot_state_publisher-3 died 4 times (exit code 1), restarted by roslaunch '
                  '(respawn)')
    # its traceback is its own, not another node's in the same log
    other = dict(TIRED, summary='ValueError: the ball', source='ros_home/log/a/ball-4.log')
    assert decide(Seen(died=[dict(DOG, node='dog-5')], errors=[other], **RUNNING))[1] == \
        'dog-5 died (exit code 1)'
    said = dict(DOG, output='Traceback ...\nValueError: the ball')
    assert decide(Seen(died=[said], errors=[TIRED, other], **RUNNING))[1] == \
        'dog-5 died (exit code 1): ValueError: the ball'
    three = [dict(QT, node='a-1'), dict(QT, node='b-2'), dict(QT, node='c-3', abort='')]
    assert decide(Seen(died=three, **RUNNING))[1].endswith('; and 1 other node')


def test_a_system_that_ended_after_doing_its_work_is_judged_by_its_checks():
    """Each end of the system (7-11) is crashed only before the checks were met."""
    ends = [dict(driver_ended=False, ended_by='driver_exit'), dict(oom=True),
            dict(ended_by='disk_limit'), dict(ended_by='required_node_died', died=[REQUIRED]),
            dict(ended_by='all_exited')]
    for end in ends:
        assert decide(Seen(**dict(ENDED, **end)))[0] == 'crashed', end
        assert decide(Seen(**dict(ENDED, checks=PASSED, **end)))[0] == 'passed', end
    # a required node that ended cleanly ends the launch all the same
    clean = dict(REQUIRED, code=0, exit='0')
    assert decide(Seen(**dict(ENDED, ended_by='required_node_died', died=[clean]))) == (
        'crashed', 'dog-5 died (exit code 0); it was required="true": roslaunch shut its launch '
                   'down at 4 of 30 simulated s')


def test_a_required_death_before_any_ground_truth_is_the_students():
    assert decide(Seen(died=[REQUIRED], ended_by='required_node_died'))[0] == 'crashed'
    # every command ended before the simulator said anything: as before, no ground truth
    assert decide(Seen(ended_by='all_exited')) == (
        'grader_error', 'the simulator never reported its ground truth')


def test_the_machines_fault_comes_before_the_students_crash():
    # the simulator died and a node died: the grader's, not the student's
    assert decide(Seen(died=[DOG, SIM], **RUNNING))[0] == 'grader_error'
    # unless the student's code killed the sandbox's processes, or broke its memory limit
    assert decide(Seen(died=[SIM], driver_ended=False, **dict(ENDED, ended_by='driver_exit'))
                  )[0] == 'crashed'
    assert decide(Seen(died=[SIM], oom=True, **ENDED))[0] == 'crashed'


def test_a_node_that_could_not_start_is_no_verdict_when_the_rest_ran():
    assert decide(Seen(launch_errors=[MISSING], **RUNNING)) == ('passed', '')
    assert decide(Seen(launch_errors=[MISSING], **dict(RUNNING, checks=FAILED)))[0] == \
        'failed_checks'


def test_a_zero_exit_is_no_death():
    assert decide(Seen(died=[dict(DOG, code=0)], **RUNNING)) == ('passed', '')


def test_a_records_own_end_comes_first_the_graders_fault_before_the_students():
    """Rows 1-5: what the record says itself decides before anything seen of a
    run; a fault of the grader's with a run that went well, or badly, is the
    grader's; and grading.yaml's refusal before what the submission holds."""
    assert decide(Seen(grader_fault=FAULT, **RUNNING))[0] == 'grader_error'
    assert decide(Seen(grader_fault=FAULT, **dict(ENDED, oom=True)))[0] == 'grader_error'
    assert decide(Seen(grader_fault=FAULT, rejected='the submission: x', **TOLD))[0] == \
        'grader_error'
    assert decide(Seen(refused='grading.yaml: x', rejected='the submission: x', **TOLD)) == (
        'grader_error', 'grading.yaml: x')
    assert decide(Seen(rejected='the submission: x', sandbox_error='no bwrap', **TOLD)) == (
        'not_built', 'the submission: x')
    # and none of them is told by the rows after: a run that never started
    assert not Seen(**TOLD).told and Seen(lost='x', **TOLD).told


def test_a_record_that_says_its_end_is_judged_on_it_alone(tmp_path):
    """verdicts.judge reads nothing of a run whose record says its end (no
    work directory, no logs): its verdict and reason only."""
    result = {'name': 'ann', 'ended_by': 'not_run', 'rejected': 'the submission: no package'}
    missing = str(tmp_path / 'nothing')
    assert verdicts.judge(missing, missing, result, None) == {
        'verdict': 'not_built', 'reason': 'the submission: no package'}
    assert verdicts.judge_told(dict(result, lost='KilledWorker')) == {
        'verdict': 'grader_error', 'reason': 'the grader lost this run: KilledWorker'}
    with pytest.raises(ValueError):
        verdicts.judge_told({'name': 'ann', 'ended_by': 'duration'})


def test_the_docs_table_lists_the_rules_row_for_row():
    """docs/grading.md's "Verdicts" table: one row a rule, in RULES' order."""
    import os
    import re
    docs = os.path.join(os.path.dirname(__file__), '..', '..', 'docs', 'grading.md')
    with open(docs) as f:
        text = f.read()
    table = text[text.index('## Verdicts'):text.index('## Isolation')]
    rows = re.findall(r'^\| (\d+) \| `(\w+)` \|', table, re.M)
    assert [int(n) for n, _ in rows] == list(range(1, len(RULES) + 1))
    assert [v for _, v in rows] == [r.verdict for r in RULES]

"""A run's figures and verdict from what the grader saw
(exp_assignment2.grading.judge.metrics, .verdicts), on hand-made records (each
verdict rule alone: test_grading_verdicts.py)."""
import json
import math
import os

from exp_assignment2.grading.judge import metrics
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.judge import roles
from exp_assignment2.grading.judge import verdicts

DOG = profiles.load('dog')
MIRO = profiles.load('miro')


def dog_states(arrive_at=10.0, wiggle=0.8, until=30.0):
    """The robot drives from (0, 0) to 1.5 m from a ball at (4, 0), then turns its head."""
    states = []
    for i in range(int(until * 10) + 1):
        t = i / 10.0
        x = min(2.5, 2.5 * t / arrive_at)
        head = wiggle * math.sin(t) if t > arrive_at else 0.0
        states.append({'t': t, 'models': {'robot': [x, 0.0, 0.1, 0.0],
                                          'ball': [4.0, 0.0, 0.5, 0.0]},
                       'joints': {'robot': {'joint_head': head, 'joint_left_wheel': t}}})
    return states


def figures(trace, profile):
    return {c['metric']: (c['value'], c['passed']) for c in metrics.evaluate(trace, profile)}


def test_a_dog_that_reaches_the_ball_and_looks_around():
    got = figures(metrics.Trace(dog_states()), DOG)
    assert got['approaches'] == (1, True)
    assert got['first_approach_time'][0] == 3.2       # within 3.2 m at x = 0.8
    assert got['looks_both_ways'] == (1.0, True)      # -0.8 .. 0.8 rad at the resting ball
    assert got['path_length'] == (2.5, True)
    assert got['python_errors'] == (0, True)


def test_a_dog_that_never_moves():
    states = [{'t': i / 10.0, 'models': {'robot': [0, 0, 0.1, 0], 'ball': [4, 0, 0.5, 0]},
               'joints': {}} for i in range(1200)]
    got = figures(metrics.Trace(states), DOG)
    assert got['approaches'] == (0, False)
    assert got['first_approach_time'] == (None, False)
    # no joint at all and nothing the simulator said of the robot: which is the
    # head cannot be told, so the check is not run (test_grading_roles.py has the rest)
    assert got['looks_both_ways'] == (None, None)
    assert got['path_length'] == (0.0, False)


def test_a_teleport_is_not_a_path():
    states = [{'t': 0.0, 'models': {'robot': [0, 0, 0, 0]}, 'joints': {}},
              {'t': 0.1, 'models': {'robot': [50, 0, 0, 0]}, 'joints': {}},
              {'t': 0.2, 'models': {'robot': [50, 1, 0, 0]}, 'joints': {}}]
    trace = metrics.Trace(states)
    assert metrics.path_length(trace, roles.find(trace, DOG), {})[0] == 1.0


def test_miro_arrivals_at_the_commanded_targets():
    states, topics = [], [(0.0, '/target_pos', {'data': [2, 0]}),
                          (20.0, '/target_pos', {'data': [2, 2]}),
                          (40.0, '/target_pos', {'data': [9, 9]})]
    for i in range(600):
        t = i / 10.0
        x, y = (min(2.0, t / 5), 0.0) if t < 20 else (2.0, min(2.0, (t - 20) / 5))
        states.append({'t': t, 'models': {'miro': [x, y, 0, 0]}, 'joints': {}})
    got = figures(metrics.Trace(states, topics), MIRO)
    assert got['arrivals'] == (2, False)       # the profile asks for 3
    assert got['arrival_ratio'] == (0.667, True)


def write_run(tmp_path, logs, events, states=()):
    work, record = tmp_path / 'work', tmp_path / 'record'
    for rel, text in logs.items():
        path = work / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    record.mkdir()
    with open(str(record / 'truth.jsonl'), 'w') as f:
        for state in states:
            f.write(json.dumps(dict(state, kind='state')) + '\n')
    result = {'events': events, 'log_sizes': {rel: len(text) for rel, text in logs.items()},
              'truth': {'states': len(states), 'sim_time': states[-1]['t'] if states else 0},
              'commands': ['roslaunch p a.launch'], 'ended_by': 'duration'}
    return str(work), str(record), result


BUILT = [{'event': 'built', 'rc': 0}, {'event': 'started', 'index': 0,
                                       'command': 'roslaunch p a.launch'}]


def test_verdicts_tell_causes_apart(tmp_path):
    def judge(name, logs, events=BUILT, states=(), **extra):
        work, record, result = write_run(tmp_path / name, logs, events, states)
        result.update(extra)
        return verdicts.judge(work, record, result, DOG)
    # the build's first error as the driver sent it, not read back out of its log
    got = judge('build', {'logs/build.log': '[original-env] something else entirely\n'},
                [{'event': 'built', 'rc': 1, 'error': {
                    'file': str(tmp_path / 'build' / 'work' / 'src' / 'src' / 'a.cpp'),
                    'line': 3, 'message': "expected ';' before 'return'"}}])
    assert (got['verdict'], got['reason']) == ('not_built', "src/a.cpp:3: expected ';' before "
                                                            "'return'")
    missing = ('ERROR: cannot launch node of type [p/dog.py]: Cannot locate node of type '
               '[dog.py] in package [p]\n')
    # nothing else ran: the node that could not start is why
    got = judge('start', {'logs/command-0.log': missing})
    assert got['verdict'] == 'not_started'
    assert got['reason'].startswith('roslaunch p a.launch: ERROR: cannot launch node of type')
    # the rest ran, as roslaunch runs it: the verdict follows the robot, the error is kept
    got = judge('missing', {'logs/command-0.log': missing}, states=dog_states())
    assert got['verdict'] == 'passed', got
    assert got['launch_errors'] == [{'command': 'roslaunch p a.launch',
                                     'line': missing.strip(), 'log': 'logs/command-0.log'}]
    # a command that started nothing, attributed to its own command (today's slip: the
    # rosrun that exited was blamed for the roslaunch's error)
    two = [{'event': 'built', 'rc': 0},
           {'event': 'started', 'index': 0, 'command': 'roslaunch p a.launch'},
           {'event': 'started', 'index': 1, 'command': 'rosrun p ghost.py'},
           {'event': 'exited', 'index': 1, 'command': 'rosrun p ghost.py', 'rc': 1}]
    got = judge('two', {'logs/command-0.log': 'RLException: Invalid roslaunch XML syntax\n',
                        'logs/command-1.log': ''}, two)
    assert (got['verdict'], got['reason']) == (
        'not_started', 'roslaunch p a.launch: RLException: Invalid roslaunch XML syntax')
    got = judge('two_b', {'logs/command-0.log': 'process[dog-1]: started with pid [9]\n',
                          'logs/command-1.log': "[rosrun] Couldn't find executable named "
                                                'ghost.py below /w\n'}, two,
                states=dog_states())
    assert (got['verdict'], got['reason']) == (
        'not_started', "rosrun p ghost.py: [rosrun] Couldn't find executable named ghost.py "
                       'below /w')
    crash = ('Traceback (most recent call last):\n  File "dog.py", line 4\n'
             'RuntimeError: the dog has no legs\n'
             '[dog-5] process has died [pid 88, exit code 1, cmd /w/dog.py __name:=dog].\n')
    # roslaunch runs on without it: judged by the checks, the death named, its traceback counted
    got = judge('crash', {'logs/command-0.log': crash}, states=dog_states(until=5))
    assert got['verdict'] == 'failed_checks', got
    assert got['reason'].endswith('; dog-5 died (exit code 1): RuntimeError: the dog has no legs')
    assert {c['name']: c['value'] for c in got['checks']}['no Python error'] == 1
    # required="true": roslaunch shut its launch down, and the run ended there
    required = crash.replace('[dog-5] process has died', '=' * 80 + 'REQUIRED process [dog-5] '
                             'has died!\nprocess has died')
    got = judge('required', {'logs/command-0.log': required}, states=dog_states(until=5),
                ended_by='required_node_died', ended_at=5.0, required_node='dog-5')
    assert (got['verdict'], got['reason']) == (
        'crashed', 'dog-5 died (exit code 1): RuntimeError: the dog has no legs; it was '
                   'required="true": roslaunch shut its launch down at 5 of 240 simulated s')
    assert got['died'][0]['required'] is True
    # judged on the truth until the crash, so that it keeps the points it earned (scores)
    assert got['checks_until'] == 'crashed' and [c['name'] for c in got['checks']] == [
        c['name'] for c in DOG['checks']]
    sim = '[gazebo-1] process has died [pid 9, exit code 1, cmd /r/scripts/simulator.py x].\n'
    got = judge('sim', {'logs/command-0.log': sim}, states=dog_states(until=5))
    assert got['verdict'] == 'grader_error' and 'the simulator died' in got['reason']
    got = judge('none', {'logs/command-0.log': 'started\n'}, [])
    assert got['verdict'] == 'grader_error'
    got = judge('slow', {'logs/command-0.log': ''}, states=dog_states(until=5),
                ended_by='wall_limit')
    assert (got['verdict'], got['reason']) == ('timed_out', '5 of 240 simulated s within the '
                                                            'wall-clock limit')
    assert got['checks_until'] == 'timed_out' and len(got['checks']) == len(DOG['checks'])
    # the run's own duration (--duration 60), not the profile's
    got = judge('slow60', {'logs/command-0.log': ''}, states=dog_states(until=5),
                ended_by='wall_limit', duration=60.0)
    assert got['reason'] == '5 of 60 simulated s within the wall-clock limit'
    got = judge('ok', {'logs/command-0.log': ''}, states=dog_states())
    assert got['verdict'] == 'passed', got
    got = judge('still', {'logs/command-0.log': ''}, states=dog_states(wiggle=0.1, until=45.0))
    assert (got['verdict'], got['reason']) == (
        'failed_checks', 'failed: head turns both ways at the ball; not judged: follows the '
                         'moving ball, gives up a hidden ball, sleeps at home, wanders')


def test_a_log_written_after_the_end_is_not_read(tmp_path):
    """What a node says while it is being stopped is not its crash."""
    text = 'fine\n'
    work, record, result = write_run(tmp_path, {'logs/command-0.log': text}, BUILT,
                                     dog_states())
    with open(os.path.join(work, 'logs', 'command-0.log'), 'a') as f:
        f.write('[dog-5] process has died [pid 88, exit code -9, cmd dog.py].\n')
    assert verdicts.judge(work, record, result, DOG)['verdict'] == 'passed'

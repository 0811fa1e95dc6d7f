"""What a failed run shows of its ROS release (exp_assignment2.grading.judge.steering;
no ROS): a follower steering for the other wheel order turns away from the ball it
sees, a controller aligning the wrong way goes nowhere, a frame lookup fails; a dog
that fails for reasons of its own shows none of these, and is not run again."""
import math

from exp_assignment2.grading.judge import steering
from exp_assignment2.grading.judge.trace import Trace
from test_grading_behaviours import DOG, ROLES, trace

CHECK = dict(DOG, checks=[])


def orbiting(offset, until=30.0):
    """The robot turns left at 0.5 rad/s on the spot; the ball circles it 4 m away at
    ``offset`` rad from its heading (negative: on its right)."""
    def robot(t):
        return (0.0, 0.0, 0.5 * t)

    def ball(t):
        return (4 * math.cos(0.5 * t + offset), 4 * math.sin(0.5 * t + offset), 0.5)
    return trace(robot, ball, until=until)


def test_turning_away_from_the_ball_it_sees_points_at_the_release():
    away = steering.evidence(orbiting(-0.35), ROLES, CHECK)
    assert away['release'] and away['turned_away'] == 1.0 and away['turning_s'] >= 20
    assert 'turned away from the ball it saw 100 %' in away['why']
    toward = steering.evidence(orbiting(0.35), ROLES, CHECK)
    assert not toward['release'] and toward['turned_away'] == 0.0
    assert toward['why'].startswith('nothing in the run points at the release: it turned '
                                    'toward the ball it saw 100 %')


def test_a_robot_that_took_commands_and_went_nowhere_points_at_the_release():
    states = [{'t': i / 10.0, 'models': {'robot': [0.01 * math.sin(i), 0, 0.1, 0.3 * i],
                                         'ball': [9, 9, -3, 0]},
               'joints': {}, 'fed': {'robot': i}} for i in range(600)]
    got = steering.evidence(Trace(states), ROLES, CHECK)
    assert got['stuck'] and got['release'] and 'drove less than 2 m' in got['why']
    idle = [dict(s, fed={'robot': 0}) for s in states]     # nothing commanded it: its own
    assert not steering.evidence(Trace(idle), ROLES, CHECK)['release']


def test_a_failed_frame_lookup_points_at_the_release():
    errors = [{'summary': 'tf2.LookupException: "odom" passed to lookupTransform argument '
                          'target_frame does not exist.'}]
    got = steering.evidence(orbiting(0.35), ROLES, CHECK, errors)
    assert got['frames'] and got['release'] and 'failed to look a frame up' in got['why']


def _failed_run(tmp_path, evidence):
    from exp_assignment2.grading import record
    from exp_assignment2.grading.plan import profiles
    from exp_assignment2.grading.plan.spec import RunSpec
    from exp_assignment2.grading.run.runner import Run, RunSettings
    profile = profiles.load('dog')
    spec = RunSpec(name='ann', path=str(tmp_path / 'ann'), kind='dir', label='ann',
                   profile=profile, duration=60.0, hidden=[], release='kinetic',
                   release_why="the course's first", releases_next=['melodic'])
    run = Run(RunSettings(profile, str(tmp_path / 'runs')), spec)
    run.result = record.write(run.record, record.RunRecord.new(
        'ann', 'ann', 1, verdict='failed_checks', release_evidence=evidence))
    return run


def test_another_release_is_tried_only_where_the_run_points_at_it(tmp_path):
    from exp_assignment2.grading import record
    from exp_assignment2.grading.run.dispatch import in_next_release
    pointed = _failed_run(tmp_path / 'a', {'release': True, 'why': 'it turned away'})
    again = in_next_release(pointed)
    assert again.spec.release == 'melodic' and again.spec.label == 'ann-melodic'
    assert again.spec.release_why.endswith('behave otherwise for it (it turned away)')
    own = _failed_run(tmp_path / 'b', {'release': False, 'why': 'nothing points at it'})
    assert in_next_release(own) is None
    kept = record.load(own.record)['teacher']['release_next']
    assert kept == {'release': 'melodic', 'tried': False, 'why': 'nothing points at it'}

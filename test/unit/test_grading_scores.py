"""A run's score from its checks and verdict (exp_assignment2.grading.judge.scores), and the
rubric's keys in a profile (no ROS)."""
import copy

import pytest

from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.judge import scores

DOG = profiles.load('dog')
MIRO = profiles.load('miro')
# the scoring's mechanics on a rubric of its own (the dog's before the behaviours' checks)
RUBRIC = profiles.check({
    'name': 'rubric', 'duration': 200, 'default_commands': ['roslaunch {package} x.launch'],
    'robot': 'robot', 'ball': 'ball', 'checks': [
        {'name': 'reaches the ball', 'metric': 'approaches', 'min': 1, 'zero': 0, 'points': 30},
        {'name': 'first reach', 'metric': 'first_approach_time', 'max': 180, 'zero': 200,
         'points': 15},
        {'name': 'head turns at the ball', 'metric': 'head_turn_near_ball', 'min': 0.6,
         'zero': 0, 'points': 25},
        {'name': 'path length', 'metric': 'path_length', 'min': 2.0, 'zero': 0, 'points': 10},
        {'name': 'no Python error', 'metric': 'python_errors', 'max': 0, 'zero': 5,
         'points': 20}]}, 'rubric')


def test_both_profiles_ship_a_rubric_of_100():
    assert scores.maximum(DOG) == 100 and scores.maximum(MIRO) == 100


def test_partial_credit_above_a_min():
    spec = {'min': 1, 'zero': 0, 'points': 30}
    assert scores.check_points(spec, 3) == 30 and scores.check_points(spec, 1) == 30
    assert scores.check_points(spec, 0.5) == 15
    assert scores.check_points(spec, 0) == 0 and scores.check_points(spec, -2) == 0
    assert scores.check_points(spec, None) == 0
    assert scores.check_points({'min': 1, 'points': 30}, 0.9) == 0     # no zero: all or none


def test_partial_credit_below_a_max():
    spec = {'max': 60, 'zero': 200, 'points': 20}
    assert scores.check_points(spec, 30) == 20 and scores.check_points(spec, 60) == 20
    assert scores.check_points(spec, 130) == 10
    assert scores.check_points(spec, 200) == 0 and scores.check_points(spec, 250) == 0
    assert scores.check_points(spec, None) == 0       # never reached: no figure


def run(verdict, values, reason='why'):
    return {'verdict': verdict, 'reason': reason,
            'checks': None if values is None else [
                {'name': c['name'], 'value': v} for c, v in zip(RUBRIC['checks'], values)]}


GOOD = [2, 40.0, 0.8, 5.0, 0]


def test_a_run_scores_the_sum_of_its_checks():
    assert scores.run_score(run('passed', GOOD), RUBRIC)['score'] == 100
    got = scores.run_score(run('failed_checks', [0, None, 0.3, 1.0, 1]), RUBRIC)
    assert [c['points'] for c in got['checks']] == [0, 0, 12.5, 5, 16]
    assert got['score'] == 33.5 and got['max'] == 100


def test_not_built_and_not_started_score_zero_with_the_reason():
    for verdict in ('not_built', 'not_started'):
        got = scores.run_score(run(verdict, None, 'src/x.py:3: nope'), RUBRIC)
        assert got['score'] == 0 and 'src/x.py:3: nope' in got['why']
        assert all(c['points'] == 0 for c in got['checks'])


def test_a_crash_keeps_the_points_earned_before_it():
    got = scores.run_score(run('crashed', [1, 100.0, 0.0, 3.0, 1]), RUBRIC)
    assert got['checks'][0]['points'] == 30 and got['checks'][3]['points'] == 10
    assert got['score'] == round(sum(c['points'] for c in got['checks']), 2) > 50
    assert 'until' in got['why']
    nothing = scores.run_score(run('crashed', None), RUBRIC)     # before any ground truth
    assert nothing['score'] == 0 and 'no check' in nothing['why']


def test_a_grader_error_has_no_score_never_zero():
    got = scores.run_score(run('grader_error', None, 'the simulator died'), RUBRIC)
    assert got['score'] is None and 'again' in got['why']
    assert all(c['points'] is None for c in got['checks'])


def test_over_repeats_the_median_run():
    scored = [(r, scores.run_score(r, RUBRIC)) for r in (
        run('passed', GOOD), run('failed_checks', [0, None, 0, 0, 0]),
        run('failed_checks', [1, 40.0, 0.3, 5.0, 0]), run('grader_error', None))]
    chosen = scores.median_run(scored)
    assert chosen[1]['score'] == 87.5       # 100, 20, 87.5: the grader error left out
    assert scores.median_run(scored[:2])[1]['score'] == 20      # even: the lower middle one
    assert scores.median_run(scored[3:]) is None


@pytest.mark.parametrize('change, says', [
    ({'pionts': 3}, "unknown key 'pionts' (did you mean 'points'?)"),
    ({'points': -1}, 'points: -1 is not a non-negative number'),
    ({'points': 'ten'}, "points: 'ten' is not a non-negative number"),
    ({'visibility': 'secret'}, "visibility: 'secret' is not one of hidden"),
    ({'zero': 5}, 'zero: 5 must be below min or above max'),
    ({'zero': 'none'}, "zero: 'none' is not a number"),
])
def test_a_wrong_rubric_key_is_one_line_naming_it(change, says):
    data = copy.deepcopy(RUBRIC)
    data['checks'][0].update(change)
    with pytest.raises(profiles.ProfileError) as error:
        profiles.check(data, 'mine.yaml')
    assert str(error.value).startswith('mine.yaml: checks[0]: ') and says in str(error.value)
    assert '\n' not in str(error.value)

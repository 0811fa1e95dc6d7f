"""``grade --calibrate``'s arithmetic (exp_assignment2.grading.judge.reference,
.plan.calibration; no ROS): the reference's distances from its ground truth,
and each threshold made of its figures with the margins docs/grading.md states."""
import math

import pytest
import yaml

from exp_assignment2.grading.judge import reference
from exp_assignment2.grading.plan import calibration, profiles
from test_grading_behaviours import ROLES, line, trace

COURSE = profiles.load('dog_course')


def test_the_reference_stops_looks_and_trails():
    """It drives to 2.8 m of the resting ball and turns its head 0.8 rad each way;
    then the ball rolls off and it trails 4 m behind, seeing it."""
    robot = lambda t: line(0, 1.2, 0, 5)(t) if t < 20 else (1.2 + 0.5 * (t - 20), 0.0, 0.0)  # noqa
    ball = lambda t: (4.0 + 0.5 * max(0.0, t - 20), 0.0, 0.5)                              # noqa
    run = trace(robot, ball, until=30, head=lambda t: 0.8 * math.sin(t) if 8 < t < 20 else 0.0)
    got = reference.distances(run, ROLES, calibration.profile_keys.with_shared({}, COURSE))
    assert got['stop_distances'] == [2.8] and got['sweeps'] == [pytest.approx(0.8, abs=0.01)]
    assert got['sweep_times'] == [pytest.approx(5.0, abs=1.0)]    # at rest ~5 s, right at 9.9
    assert got['trailing'] and all(abs(d - 2.8) < 0.1 for d in got['trailing'])


def test_each_threshold_is_the_references_figure_with_its_margin(monkeypatch, tmp_path):
    found = [{'stop_distances': [2.71, 2.84], 'sweeps': [0.8, 0.78], 'sweep_times': [12.0, 9.5],
              'trailing': [3.0] * 30 + [5.0] * 10, 'per_place': [10.8],
              'asleep_after': [34.0, 15.8]},
             {'stop_distances': [2.9], 'sweeps': [0.8], 'sweep_times': [30.0],
              'trailing': [4.0] * 4, 'per_place': [15.3], 'asleep_after': [16.2]}]
    figures = [{'follows_ball': (0.8, 50.0), 'looks_both_ways': (1.0, 60.0),
                'gives_up_ball': (14.0, 90.0), 'sleeps': (15.2, 40.0), 'wanders': (9, 20.0),
                'first_approach_time': (40.0, 40.0)},
               {'follows_ball': (0.7, 50.0), 'looks_both_ways': (0.75, 60.0),
                'gives_up_ball': (18.1, 90.0), 'sleeps': None, 'wanders': (6, 20.0),
                'first_approach_time': (52.0, 52.0)}]
    monkeypatch.setattr(reference, 'distances', lambda t, r, c: found.pop(0))
    monkeypatch.setattr(reference, 'figures', lambda t, r, p: figures[t])
    monkeypatch.setattr(reference, 'shown_by', lambda t, r, p: (140.0, 152.0)[t])
    lines = []
    got = calibration.derive(COURSE, [(0, ROLES), (1, ROLES)], lines.append)
    checks = {c['metric']: c for c in got['checks']}
    assert got['reach'] == 3.2                                  # 2.9 + 10 %, up to 0.1 m
    assert checks['looks_both_ways']['angle'] == 0.35           # half of 0.78, down to 0.05
    assert checks['looks_both_ways']['window'] == 40            # 30 s + 25 %, up to 5 s
    assert checks['wanders']['per'] == 35                       # twice 15.3 s, up to 5 s
    assert checks['sleeps']['unseen'] == 30                     # twice 15.8 s, down to 5 s
    assert checks['follows_ball']['follow'] == 4.5              # 3/4 of them within 4.0; + 10 %
    assert checks['follows_ball']['min'] == 0.55                # 0.7 - 20 %
    assert checks['looks_both_ways']['min'] == 0.6              # 0.75 - 20 %
    assert (checks['gives_up_ball']['max'], checks['gives_up_ball']['zero']) == (25, 50)
    assert (checks['sleeps']['min'], checks['sleeps']['zero']) == (7, 3.5)   # half of 15.2
    assert checks['wanders']['min'] == 3                        # half of 6
    assert got['duration'] == 170 and checks['sleeps']['occasion'] == 170   # 152 + 10 %
    assert (checks['first_approach_time']['max'], checks['first_approach_time']['zero']) == (
        70, 170)
    assert len(lines) == 13 and lines[0].startswith('reach 3.2 m: the reference came to rest')
    calibration.write(str(tmp_path / 'dog.yaml'), got, lines, '/ref')
    text = (tmp_path / 'dog.yaml').read_text()
    assert text.startswith('# Calibrated by: bash tools/run grade --calibrate /ref\n')
    again = profiles.load(str(tmp_path / 'dog.yaml'))
    assert again['reach'] == 3.2 and again['ball_script'] == COURSE['ball_script']
    assert yaml.safe_load(text)['ball'] == {'name': 'ball', 'script': {'seeds': [1]}}

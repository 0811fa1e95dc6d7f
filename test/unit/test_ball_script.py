"""The ball's course (sim.ball_script, sim.ball_places, sim.ball_setting): pure,
seeded, every occasion of the dog's behaviours within the run, places inside
the arena and clear of its objects, continuous play, one-line refusals."""
import json
import math

import pytest

from exp_assignment2.sim import ball_script, ball_setting
from exp_assignment2.sim.ball_script import (HIDDEN_Z, Arena, ScriptError, from_legs,
                                             make_script, play, to_json_legs)
from exp_assignment2.sim.scripted_ball import world_arena

# the dog's world: bounds of the ball's centre, the person's chair and the kennel
DOG = Arena(-8.8, 8.8, -8.8, 8.8, obstacles=((-7.35, -6.65, 6.65, 7.35), (6.4, 7.6, 6.4, 7.6)))
SEEDS = range(200)


def visible_stops(script, end):
    """(t0, t1, (x, y)) of every stretch at rest and shown that ends by ``end``."""
    return [(s.t0, s.t1, (s.x0, s.y0)) for s in script.segments
            if not s.hidden and (s.x0, s.y0) == (s.x1, s.y1) and s.t1 <= end]


def hides(script, end):
    return [(s.t0, s.t1) for s in script.segments if s.hidden and s.t1 <= end]


def test_the_same_seed_gives_the_same_course_and_another_seed_another():
    first = make_script(3, DOG)
    again = make_script(3, Arena(*DOG))
    assert first == again
    assert len({json.dumps(to_json_legs(make_script(seed, DOG).legs)) for seed in SEEDS}) \
        == len(SEEDS)


def test_no_global_random_state_is_used_or_touched():
    import random
    random.seed(1)
    before = random.random()
    random.seed(1)
    make_script(5, DOG)
    assert random.random() == before
    random.seed(99)
    assert make_script(5, DOG) == make_script(5, DOG)


@pytest.mark.parametrize('duration', [200.0, 300.0, 600.0])
def test_every_occasion_of_the_dogs_behaviours_comes_within_the_run(duration):
    for seed in SEEDS:
        script = make_script(seed, DOG, {'duration': duration})
        assert play(script, 0.0).hidden and play(script, 0.0).z == HIDDEN_Z
        assert script.segments[0].hidden and script.segments[0].t1 >= 20.0   # wanders, sleeps
        stops = visible_stops(script, duration)
        assert len({place for _, _, place in stops}) >= 3, seed
        assert any(t1 - t0 >= 8.0 for t0, t1, _ in stops), seed            # the head's sweep
        # hidden again long enough to give up, after it was seen, then back
        later = [(t0, t1) for t0, t1 in hides(script, duration) if t0 > 0 and t1 - t0 >= 20.0]
        assert later, seed
        back = later[0][1]
        assert any(t0 >= back for t0, _, _ in stops), seed
        assert not play(script, back + 0.01).hidden


def test_a_shorter_run_shrinks_the_times_and_keeps_the_order():
    for seed in SEEDS:
        script = make_script(seed, DOG, {'duration': 60.0})
        assert play(script, 0.0).hidden
        later = [(t0, t1) for t0, t1 in hides(script, 60.0) if t0 > 0]
        assert later and any(t0 >= later[0][1] for t0, _, _ in visible_stops(script, 60.0))
        assert max(s.t1 - s.t0 for s in script.segments if s.hidden) <= 30 * 0.3 + 1e-9


def test_places_stay_inside_the_arena_with_a_margin_and_clear_of_its_objects():
    for seed in SEEDS:
        for leg in make_script(seed, DOG).legs:
            if leg.place is None:
                continue
            x, y = leg.place
            assert -7.8 <= x <= 7.8 and -7.8 <= y <= 7.8, (seed, leg)
            for x0, x1, y0, y1 in DOG.obstacles:
                gap = math.hypot(max(x0 - x, 0, x - x1), max(y0 - y, 0, y - y1))
                assert gap >= 1.5, (seed, leg)


def test_a_room_too_small_is_one_line():
    with pytest.raises(ScriptError) as err:
        make_script(1, Arena(0, 1.5, 0, 1.5))
    assert 'leaves no room' in str(err.value) and '\n' not in str(err.value)


@pytest.mark.parametrize('seed', [0, 7, 42])
def test_play_is_continuous_but_for_the_hides_and_shows(seed):
    script = make_script(seed, DOG)
    dt, last = 0.01, play(script, 0.0)
    fastest = max(leg.speed or 0 for leg in script.legs)
    for k in range(1, int(script.segments[-1].t1 / dt) + 200):
        now = play(script, k * dt)
        if now.hidden == last.hidden:
            assert math.hypot(now.x - last.x, now.y - last.y) <= fastest * dt + 1e-9, k * dt
            assert now.z == last.z
        last = now
    assert play(script, 1e6) == play(script, script.segments[-1].t1)


def test_play_moves_at_the_legs_speed_and_says_its_velocity():
    script = from_legs([{'show': [0, 0], 'stay': 2}, {'move': [3, 4], 'speed': 0.5, 'stay': 1},
                        {'hide': 5}, {'show': [1, 1]}], given={'ground_z': 0.3})
    assert play(script, -1.0) == play(script, 0.0)
    assert play(script, 1.0)[:4] == (0, 0, 0.3, False)
    mid = play(script, 7.0)                                  # 5 of 10 s on the way
    assert (mid.x, mid.y) == pytest.approx((1.5, 2.0)) and (mid.vx, mid.vy) == (0.3, 0.4)
    assert play(script, 12.5)[:4] == (3, 4, 0.3, False) and play(script, 12.5).vx == 0
    assert play(script, 14.0)[:4] == (3, 4, HIDDEN_Z, True)
    assert play(script, 18.0)[:4] == (1, 1, 0.3, False)


def test_a_seeded_course_is_the_same_given_by_hand():
    script = make_script(11, DOG)
    again = from_legs(json.loads(json.dumps(to_json_legs(script.legs))))
    assert again.segments == script.segments and again.seed is None


@pytest.mark.parametrize('legs,words', [
    ([{'show': [float('nan'), 1]}], 'leg 1 {"show": [NaN, 1]}: the place must be [x, y], two '
                                    'finite numbers'),
    ([{'hide': 3}, {'show': [12, 0], 'stay': 1}], 'leg 2 {"show": [12, 0], "stay": 1}: the '
                                                  'place (12, 0) is outside the arena'),
    ([{'hide': -2}], 'leg 1 {"hide": -2}: the hide is negative (-2 s)'),
    ([{'show': [0, 0], 'stay': -1}], 'stay is negative'),
    ([{'show': [0, 0]}, {'move': [1, 1], 'speed': 0}], 'leg 2 {"move": [1, 1], "speed": 0}: '
                                                       'speed must be a positive number'),
    ([{'show': [0, 0], 'speed': 1}], 'unknown key speed for a show'),
    ([{'hide': 1, 'show': [0, 0]}], 'give exactly one of hide, show, move'),
    ([{'move': [1, 1], 'speed': 1}], 'leg 1 {"move": [1, 1], "speed": 1}: a move starts where '
                                     'the ball is shown: show it first'),
    ([], 'legs must be a non-empty list'),
    ([{'hide': True}], 'the hide must be a finite number of seconds, got true'),
])
def test_a_bad_leg_is_refused_with_one_line_naming_it(legs, words):
    with pytest.raises(ScriptError) as err:
        from_legs(legs, Arena(-8.8, 8.8, -8.8, 8.8))
    assert words in str(err.value) and '\n' not in str(err.value)
    assert str(err.value).startswith('ball script: ')


def test_the_setting_is_a_seed_or_legs_from_the_parameter_else_the_environment():
    env = {ball_setting.ENV: '{"seed": 3, "model": "toy"}'}
    assert ball_setting.choose(None, env) == ball_setting.BallSetting(3, None, 'toy', 200.0)
    assert ball_setting.choose('{"seed": 4, "duration": 60}', env).seed == 4
    assert ball_setting.choose({'seed': 5}, env).seed == 5              # a YAML parameter
    assert ball_setting.choose('', {}) is None and ball_setting.choose(None, {}) is None
    given = ball_setting.choose('{"legs": [{"hide": 2}, {"show": [1, 2], "stay": 3}]}', {})
    assert given.seed is None and [leg.kind for leg in given.legs] == ['hide', 'show']
    assert given.to_dict() == {'legs': [{'hide': 2.0}, {'show': [1.0, 2.0], 'stay': 3.0}],
                               'duration': 200.0}
    assert ball_setting.choose(None, env).describe() == 'seed 3, 200 s, model toy'


@pytest.mark.parametrize('value,words', [
    ('{"seed": 3', 'is not JSON'),
    ('[3]', 'expected a JSON object'),
    ('{"sed": 3}', "unknown key 'sed' (known: seed, legs, model, duration)"),
    ('{"seed": 3, "legs": []}', 'give exactly one of seed or legs'),
    ('{"seed": -1}', 'the seed must be a whole number >= 0'),
    ('{"seed": 2.5}', 'the seed must be a whole number >= 0'),
    ('{"seed": 1, "duration": 0}', 'duration must be a positive number'),
    ('{"seed": 1, "model": ""}', "model must be a model's name"),
    ('{"legs": [{"hide": NaN}]}', 'leg 1 {"hide": NaN}: the hide must be a finite number'),
])
def test_a_bad_setting_is_one_line_naming_where_it_came_from(value, words):
    with pytest.raises(ScriptError) as err:
        ball_setting.choose(None, {ball_setting.ENV: value})
    assert str(err.value).startswith(ball_setting.ENV + ': ') and words in str(err.value)
    assert '\n' not in str(err.value)
    with pytest.raises(ScriptError) as err:
        ball_setting.choose(value, {})
    assert str(err.value).startswith('~ball_script: ')


def test_the_arena_is_the_worlds_bounds_else_its_walls_else_the_courses():
    floor = ((-10, -10, -0.1), (10, 10, 0.0))
    walls = [((-6.1, 5.9, 0), (6.1, 6.1, 1)), ((-6.1, -6.1, 0), (6.1, -5.9, 1)),
             ((5.9, -6.1, 0), (6.1, 6.1, 1)), ((-6.1, -6.1, 0), (-5.9, 6.1, 1))]
    post = ((-3.15, 2.85, 0), (-2.85, 3.15, 1.2))
    bounded = world_arena((-8.8, 8.8, -8.8, 8.8), [floor, post], 0.5)
    assert bounded[:4] == (-8.8, 8.8, -8.8, 8.8)
    assert bounded.obstacles == ((-3.15, -2.85, 2.85, 3.15),)        # the floor is no obstacle
    inf = (-math.inf, math.inf, -math.inf, math.inf)
    walled = world_arena(inf, [floor, post] + walls, 0.5)
    assert walled[:4] == pytest.approx((-5.6, 5.6, -5.6, 5.6)) and len(walled.obstacles) == 5
    for seed in range(50):               # the walls are kept clear of, as any object
        for leg in make_script(seed, walled).legs:
            assert leg.place is None or max(map(abs, leg.place)) <= 4.4
    assert world_arena(inf, [floor, post], 0.5)[:4] == (-8.0, 8.0, -8.0, 8.0)
    assert world_arena(inf, [], 0.5)[:4] == (-8.0, 8.0, -8.0, 8.0)


def test_the_options_are_checked():
    with pytest.raises(ScriptError, match='unknown option speed'):
        ball_script.options({'speed': 3})
    with pytest.raises(ScriptError, match='duration must be a positive'):
        make_script(1, DOG, {'duration': -5})
    with pytest.raises(ScriptError, match='the seed must be a whole number'):
        make_script('3', DOG)

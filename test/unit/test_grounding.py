"""Scenario B's grounding and simulated person (no ROS master)."""
import random

import pytest

from exp_assignment2.commands import CommandError, parse_voice
from exp_assignment2.grounding import ground
from exp_assignment2.miro_person import SimulatedPerson


def test_go_home_uses_the_home_parameters():
    assert ground('go_home', (3, 3), random.Random(0)) == (3, 3)
    assert ground('go_home', (7, 2), random.Random(0)) == (7, 2)


def test_go_rand_stays_on_the_grid_and_is_seeded():
    points = [ground('go_rand', (3, 3), random.Random(5)) for _ in range(3)]
    assert len(set(points)) == 1                       # same seed, same point
    rng = random.Random(1)
    for _ in range(500):
        x, y = ground('go_rand', (3, 3), rng)
        assert 0 <= x <= 9 and 0 <= y <= 9


def test_go_to_gives_the_point():
    assert ground('go to 4 10', (3, 3), random.Random(0)) == (4, 10)


@pytest.mark.parametrize('text', ['go to 4', 'go to 4 11', 'go to -1 0', 'fly', ''])
def test_bad_commands_are_not_grounded(text):
    with pytest.raises(CommandError):
        ground(text, (3, 3), random.Random(0))


def test_simulated_person_is_seeded_and_speaks_the_grammar():
    a, b = SimulatedPerson(seed=7), SimulatedPerson(seed=7)
    said_a = [a.says(playing=i % 2 == 0) for i in range(200)]
    said_b = [b.says(playing=i % 2 == 0) for i in range(200)]
    assert said_a == said_b
    spoken = [s for s in said_a if s]
    assert spoken and any(s.startswith('go to') for s in spoken)
    assert {'play', 'hey buddy'} & set(spoken)
    for text in spoken:
        parse_voice(text)                  # every simulated sentence is valid
    for _ in range(100):
        (px, py), (gx, gy) = a.gesture()
        assert all(0 <= v <= 10 for v in (px, py, gx, gy))


def test_simulated_person_only_calls_when_not_playing():
    person = SimulatedPerson(seed=3)
    for _ in range(200):
        assert person.says(playing=False) in ('', 'play', 'hey buddy')

"""Scenario B's grounding: a motion command becomes a grid point (no ROS)."""
import random

import pytest

from exp_assignment2.grammar import CommandError
from exp_assignment2.grounding import ground


def test_go_home_uses_the_home_parameters():
    assert ground('go_home', (3, 3), random.Random(0)) == (3, 3)
    assert ground('go_home', (7, 2), random.Random(0)) == (7, 2)


def test_go_rand_stays_on_the_grid_and_is_seeded():
    points = [ground('go_rand', (3, 3), random.Random(5)) for _ in range(3)]
    assert len(set(points)) == 1                       # same seed, same point
    rng = random.Random(1)
    seen = {ground('go_rand', (3, 3), rng) for _ in range(2000)}
    assert all(0 <= x <= 9 and 0 <= y <= 9 for x, y in seen)
    assert len(seen) == 100, 'every point of 0..9 x 0..9 comes up'


def test_go_to_gives_the_point():
    assert ground('go to 4 10', (3, 3), random.Random(0)) == (4, 10)


@pytest.mark.parametrize('text', ['go to 4', 'go to 4 11', 'go to -1 0', 'fly', '',
                                  'go to \u0664 1'])
def test_bad_commands_are_not_grounded(text):
    with pytest.raises(CommandError):
        ground(text, (3, 3), random.Random(0))

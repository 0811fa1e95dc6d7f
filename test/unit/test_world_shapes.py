"""The world's scenery for rviz, from the models that build the physics (no ROS)."""
import numpy as np
import pytest

from exp_assignment2.behaviour.person import Person
from exp_assignment2.sim import world_shapes
from exp_assignment2.sim.offline import make_engine


@pytest.fixture(scope='module')
def dog():
    engine = make_engine()
    yield engine
    engine.close()


def test_the_scenery_is_the_static_models(dog):
    names = [m.name for m in world_shapes.scenery(dog.models.values())]
    assert names == ['arena', 'human', 'kennel']


def test_shapes_are_posed_in_the_world(dog):
    shapes = world_shapes.shapes(dog.models.values())
    walls = [s for s in shapes if s.model == 'arena' and s.params.get('size', (0, 0, 0))[2] == 1]
    assert sorted(round(float(abs(s.pose[0, 3]) + abs(s.pose[1, 3])), 2) for s in walls) == [
        9.4] * 4
    mat = [s for s in shapes if s.model == 'kennel'][0]
    np.testing.assert_allclose(mat.pose[:2, 3], (7.0, 7.0))
    head = [s for s in shapes if s.model == 'human' and s.kind == 'sphere'][0]
    assert head.pose[2, 3] == pytest.approx(1.25)


def test_the_grid_lies_on_the_floor_at_whole_metres():
    for world, first, last in (('world_dog.yaml', -10.0, 10.0), ('world_miro.yaml', 0.0, 10.0)):
        engine = make_engine(world)
        try:
            lines = world_shapes.grid_lines(engine.models.values())
        finally:
            engine.close()
        xs = sorted({a[0] for a, b in lines if a[0] == b[0]})
        assert (xs[0], xs[-1], len(xs)) == (first, last, int(last - first) + 1)
        assert all(a[2] == pytest.approx(0.005) for a, _ in lines)


def test_the_signature_changes_when_a_static_model_moves(dog):
    before = world_shapes.signature(dog.models.values())
    dog.models['kennel'].set_pose((6.0, 7.0, 0.0))
    assert world_shapes.signature(dog.models.values()) != before
    dog.models['kennel'].set_pose((7.0, 7.0, 0.0))
    assert world_shapes.signature(dog.models.values()) == before


def test_the_person_says_where_a_gesture_puts_them():
    moves = []
    person = Person((5, 5), on_move=moves.append)
    person.saw_gesture((4, 4), (8, 2))
    person.saw_gesture((4, 4), (1, 1))
    person.saw_gesture((2, 6), (1, 1))
    assert moves == [(4, 4), (2, 6)]

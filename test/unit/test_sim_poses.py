"""Where Gazebo's services may put a body, and how fast (no ROS)."""
import math
from types import SimpleNamespace

import pytest

from exp_assignment2.sim.poses import MAX_COORDINATE, PoseError, check_in_world, twist_tuple

DOG = (-8.8, 8.8, -8.8, 8.8)
SDF = (-math.inf, math.inf, -math.inf, math.inf)


def test_a_body_goes_within_the_worlds_bounds_and_a_metre_beyond():
    for inside in ((0.0, 0.0, 0.1), (9.8, -9.8, 2.0), (1.0, 1.0, -1.0)):   # z < 0 hides the ball
        assert check_in_world(DOG, inside) == inside
    for outside in ((9.9, 0.0, 0.1), (100.0, 0.0, 0.1), (1.0e300, 0.0, 0.1), (0.0, 0.0, 2e5)):
        with pytest.raises(PoseError, match=r'is outside the world \(x in \[-9.8, 9.8\]'):
            check_in_world(DOG, outside)


def test_a_world_without_bounds_stops_where_physics_breaks():
    assert check_in_world(SDF, (1000.0, -1000.0, 5.0)) == (1000.0, -1000.0, 5.0)
    with pytest.raises(PoseError, match=r'x in \[-100000, 100000\]'):
        check_in_world(SDF, (MAX_COORDINATE * 2, 0.0, 0.0))


def twist(vx=0.0, wz=0.0):
    return SimpleNamespace(linear=SimpleNamespace(x=vx, y=0.0, z=0.0),
                           angular=SimpleNamespace(x=0.0, y=0.0, z=wz))


def test_a_twist_is_finite_and_at_most_1000():
    assert twist_tuple(twist(3.0, -2.0)) == ((3.0, 0.0, 0.0), (0.0, 0.0, -2.0))
    with pytest.raises(PoseError, match='faster than 1000 m/s or rad/s'):
        twist_tuple(twist(wz=1.0e4))
    with pytest.raises(PoseError, match='not finite'):
        twist_tuple(twist(vx=math.inf))

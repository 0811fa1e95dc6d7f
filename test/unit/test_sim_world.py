"""The simulator's world description and pacing, offline (no ROS, no pybullet)."""
import math
import os

import pytest
import yaml

from exp_assignment2.sim.pacing import Pacer
from exp_assignment2.sim.world import parse_world

CONFIG = os.path.join(os.path.dirname(__file__), '..', '..', 'config')


def world(**model):
    desc = dict(name='m', urdf='x.urdf')
    desc.update(model)
    return {'models': [desc]}


@pytest.mark.parametrize('name', ['world_dog.yaml', 'world_miro.yaml'])
def test_the_shipped_worlds_parse(name):
    with open(os.path.join(CONFIG, name)) as f:
        spec = parse_world(yaml.safe_load(f))
    assert spec.models and all(m.name for m in spec.models)


def test_the_dog_world_has_the_spec_s_models_and_places():
    with open(os.path.join(CONFIG, 'world_dog.yaml')) as f:
        spec = parse_world(yaml.safe_load(f))
    models = {m.name: m for m in spec.models}
    robot, ball = models['robot'], models['ball']
    assert robot.pose[:2] == (-5.0, 7.0) and robot.pose[5] == pytest.approx(math.pi, abs=1e-4)
    assert ball.pose[:3] == (-7.0, 6.0, 0.5)
    assert models['human'].pose[:2] == (-7.0, 7.0)
    assert robot.description_param() == '/robot/robot_description'
    assert ball.description_param() == '/ball_description'
    assert models['arena'].grid and not robot.grid


@pytest.mark.parametrize('desc,key', [
    (world(nmae='x'), "'nmae'"),
    (world(plugins={'diff_drive': {}}), "<gazebo> tags"),
    ({'models': [], 'bound': [0, 1, 0, 1]}, "'bound'"),
])
def test_an_unknown_key_is_an_error_that_names_it(desc, key):
    with pytest.raises(ValueError, match=key):
        parse_world(desc)


@pytest.mark.parametrize('desc,why', [
    (world(pose=[0, 0, 0]), 'pose must be'),
    (world(pose=[0, 0, 'a', 0]), 'must be a number'),
    (world(pose=[0, 0, float('nan'), 0]), 'must be finite'),
    (world(description='/p'), 'exactly one of'),
    ({'models': [{'name': 'a', 'urdf': 'x'}, {'name': 'a', 'urdf': 'y'}]}, 'unique'),
    ({'models': {}}, 'must be a list'),
    (dict(world(), bounds=[1, 0, 0, 1]), 'empty'),
])
def test_malformed_worlds_are_refused_with_the_reason(desc, why):
    with pytest.raises(ValueError, match=why):
        parse_world(desc)


def test_an_empty_world_is_a_world_and_poses_take_roll_and_pitch():
    assert parse_world({}).models == []
    spec = parse_world(world(pose=[1, 2, 3, 0.1, 0.2, 0.3], namespace='/robot2/'))
    assert spec.models[0].pose == (1, 2, 3, 0.1, 0.2, 0.3)
    assert spec.models[0].namespace == 'robot2'
    assert parse_world(world(pose=[1, 2, 3, 4])).models[0].pose == (1, 2, 3, 0, 0, 4)


class FakeWall(object):
    def __init__(self):
        self.t = 0.0

    def __call__(self):
        return self.t


@pytest.mark.parametrize('rtf', [1.0, 2.0, 0.5])
def test_pacing_holds_simulated_time_to_the_real_time_factor(rtf):
    wall = FakeWall()
    pacer = Pacer(rtf, wall=wall)
    pacer.restart(0.0)
    sim = 0.0
    for _ in range(1000):
        sim += 0.01                      # a step takes no wall time
        wall.t += pacer.delay(sim)       # ... and the loop sleeps as told
    assert sim / wall.t == pytest.approx(rtf, rel=1e-6)


def test_pacing_at_zero_runs_at_its_ceiling_and_without_one_never_waits():
    wall = FakeWall()
    pacer = Pacer(0.0, wall=wall, max_real_time_factor=20.0)
    pacer.restart(0.0)
    sim = 0.0
    for _ in range(1000):
        sim += 0.01
        wall.t += pacer.delay(sim)
    assert sim / wall.t == pytest.approx(20.0, rel=1e-6)
    assert Pacer(0.0).pace == 20.0                   # the default ceiling
    unbounded = Pacer(0.0, wall=wall, max_real_time_factor=0.0)
    assert all(unbounded.delay(t * 0.01) == 0.0 for t in range(100))


def test_a_loop_of_short_steps_waits_every_other_step_and_keeps_to_the_wall():
    wall = FakeWall()
    pacer = Pacer(1.0, wall=wall)                # min_ahead 2 ms, the default
    pacer.restart(0.0)
    sim, waits = 0.0, 0
    for _ in range(1000):
        sim += 0.001                             # the simulator's 1 kHz
        wait = pacer.delay(sim)
        waits += wait > 0
        wall.t += wait
        assert 0.0 <= sim - wall.t < pacer.min_ahead + 0.001
    assert 490 <= waits <= 500                   # every other (sums of 0.001 round)
    every_step = Pacer(1.0, wall=wall, min_ahead=0.0)
    every_step.restart(sim)
    assert every_step.delay(sim + 0.001) == pytest.approx(0.001)
    fast = Pacer(20.0, wall=wall)                # 2 simulated ms at any factor
    fast.restart(sim)
    assert fast.delay(sim + 0.001) == 0.0
    assert fast.delay(sim + 0.002) == pytest.approx(0.0001)


def test_a_loop_that_falls_behind_starts_again_instead_of_racing():
    wall = FakeWall()
    pacer = Pacer(1.0, wall=wall, max_lag=0.25)
    pacer.restart(0.0)
    wall.t = 2.0                          # a 2 s hiccup
    assert pacer.delay(0.01) == 0.0       # behind: no wait, and a new start
    assert pacer.delay(0.02) == pytest.approx(0.01)


@pytest.mark.parametrize('rtf', [-1.0, float('nan'), float('inf')])
def test_pacing_refuses_a_bad_factor(rtf):
    with pytest.raises(ValueError):
        Pacer(rtf)

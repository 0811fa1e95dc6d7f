"""The engine playing a ball script (sim.scripted_ball): the same ball in
every run of a seed whatever a student's node sends it, every command to it
ignored and counted in the ground truth (offline, no master)."""
import math
import os
import random

import pytest

from exp_assignment2.sim import ball_script
from exp_assignment2.sim.engine import Engine
from exp_assignment2.sim.ground_truth import GroundTruth
from exp_assignment2.sim.offline import URDF_DIR
from exp_assignment2.sim.plugins.cores import CORES
from fakes import RecordingLog

BOUNDS = (-8.8, 8.8, -8.8, 8.8)
SEED = '{"seed": 3, "duration": 40}'        # 40 s: the times shrink (hidden 4-6 s first)


def urdf(name):
    with open(os.path.join(URDF_DIR, name)) as f:
        return f.read()


def world(setting=SEED, ball_at=None, **kwargs):
    """The dog's scenery and its ball (``ball_at``: spawned later, by hand)."""
    engine = Engine(registry=CORES, bounds=BOUNDS, real_time_factor=0, log=RecordingLog(),
                    settings={'ball_script': setting}, **kwargs)
    engine.spawn('arena', urdf('arena.urdf'))
    engine.spawn('human', urdf('human.urdf'), (-7.0, 7.0, 0.0, -0.785))
    engine.spawn('kennel', urdf('kennel.urdf'), (7.0, 7.0, 0.0, 0.0))
    if ball_at is None:
        engine.spawn('ball', urdf('ball.urdf'), (-7.0, 6.0, 0.5, 0.0), namespace='ball')
    return engine


class Link(object):
    def __init__(self):
        self.records = []

    def send(self, record, droppable=False):
        self.records.append(record)


def ball_track(engine, seconds, student=None):
    """The ground truth's ball poses {t: [x, y, z, yaw]} over ``seconds``;
    ``student(engine, rng)`` runs before every step."""
    link, rng = Link(), random.Random(7)
    truth = GroundTruth(engine, link)
    engine.step_listeners.append(truth)
    for _ in range(int(round(seconds / engine.time_step))):
        if student is not None:
            student(engine, rng)
        engine.step()
    return link, {r['t']: r['models']['ball'] for r in link.records if r['kind'] == 'state'}


def busy_student(engine, rng):
    """A student's ball node: cmd_vel every step, a teleport now and then."""
    ball = engine.models['ball']
    drive = engine.plugins['ball'][0]
    drive.command.command(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-1, 1))
    if rng.random() < 0.02:
        ball.set_pose((rng.uniform(-8, 8), rng.uniform(-8, 8), rng.choice((0.5, -3.0))))


def test_the_same_seed_gives_the_same_ball_whatever_the_student_sends():
    idle, busy = world(), world()
    try:
        _, calm = ball_track(idle, 30.0)
        link, pushed = ball_track(busy, 30.0, busy_student)
        assert len(calm) == len(pushed) > 290 and list(calm) == list(pushed)
        for t in calm:
            assert pushed[t] == pytest.approx(calm[t], abs=1e-3), t
        hidden = [t for t in calm if calm[t][2] == ball_script.HIDDEN_Z]
        shown = [t for t in calm if calm[t][2] == 0.5]
        assert hidden and hidden[0] == min(calm) and shown and min(shown) > 3.0
        xs = {round(calm[t][0], 2) for t in shown}
        assert len(xs) > 20                              # it moved while shown
        # what the student sent: ignored, counted, never fed nor placed
        last = [r for r in link.records if r['kind'] == 'state'][-1]
        assert 'ball' not in last.get('fed', {}) and 'ball' not in last.get('placed', {})
        assert last['ignored']['ball'] > 3000
        assert busy.models['ball'].ignored > 0
    finally:
        idle.close()
        busy.close()


def test_the_ball_is_played_from_its_spawn_and_said_scripted_in_the_ground_truth():
    engine = world(ball_at=5.0)
    link = Link()
    truth = GroundTruth(engine, link)
    engine.step_listeners.append(truth)
    engine.run_for(5.0)
    ball = engine.spawn('toy', urdf('ball.urdf'), (0.0, 0.0, 0.5, 0.0), namespace='toy')
    script, start = engine.scripted_ball.script, engine.scripted_ball.start
    assert start == pytest.approx(5.0) and ball.hidden and ball.pose()[0][2] == -3.0
    engine.run_for(20.0)
    where = ball_script.play(script, engine.time - start)
    assert ball.pose()[0] == pytest.approx((where.x, where.y, where.z))
    hello = link.records[0]
    assert hello['kind'] == 'hello' and hello['ball_script'] == {'seed': 3, 'duration': 40.0}
    facts = [r['facts'] for r in link.records if r['kind'] == 'model']
    scripted = {f['name']: f['scripted'] for f in facts}
    assert scripted['arena'] is None and scripted['toy']['seed'] == 3
    assert scripted['toy']['start'] == pytest.approx(5.0)
    assert scripted['toy']['legs'] == ball_script.to_json_legs(script.legs)
    assert "follows the course's script (seed 3" in engine.log.text()
    engine.close()


def test_reset_and_respawn_keep_the_course():
    engine = world()
    try:
        engine.run_for(12.0)
        engine.reset_world()                    # the ball is not put back at its spawn
        script, ball = engine.scripted_ball.script, engine.models['ball']
        where = ball_script.play(script, engine.time)
        assert ball.pose()[0] == pytest.approx((where.x, where.y, where.z))
        engine.delete('ball')
        engine.run_for(3.0)
        engine.spawn('ball', urdf('ball.urdf'), (-7.0, 6.0, 0.5, 0.0), namespace='ball')
        engine.run_for(1.0)
        where = ball_script.play(script, engine.time)
        assert engine.models['ball'].pose()[0] == pytest.approx((where.x, where.y, where.z))
    finally:
        engine.close()


def test_the_model_named_is_held_even_a_dynamic_one_and_other_spheres_are_left_alone():
    red = urdf('ball.urdf').replace('<gazebo reference="ball_link"><gravity>0</gravity>'
                                    '</gazebo>', '')
    engine = world('{"seed": 1, "model": "red", "duration": 40}')
    try:
        engine.spawn('red', red, (2.0, 2.0, 3.0, 0.0), namespace='red')
        assert engine.models['ball'].script is None and engine.models['red'].script
        engine.run_for(10.0)
        red_ball = engine.models['red']
        where = ball_script.play(engine.scripted_ball.script, engine.time)
        assert red_ball.pose()[0] == pytest.approx((where.x, where.y, where.z))  # no falling
        engine.models['ball'].set_pose((1.0, 1.0, 0.5))
        assert engine.models['ball'].placed == 1           # the student's own sphere
    finally:
        engine.close()


def test_a_sphere_with_a_camera_or_a_drive_is_not_taken_for_the_ball():
    drive = '<gazebo><plugin name="d" filename="libgazebo_ros_diff_drive.so"/></gazebo>'
    camera = ('<gazebo reference="ball_link"><sensor type="camera" name="c">'
              '<plugin name="p" filename="libgazebo_ros_camera.so"/></sensor></gazebo>')
    # no plugin is served: what the URDF says is what counts
    engine = Engine(bounds=BOUNDS, log=RecordingLog(), settings={'ball_script': SEED})
    try:
        engine.spawn('arena', urdf('arena.urdf'))
        engine.spawn('rover', urdf('ball.urdf').replace('<gazebo>', drive + '<gazebo>', 1))
        engine.spawn('eye', urdf('ball.urdf').replace('<gazebo>', camera + '<gazebo>', 1))
        assert [m.script for m in engine.models.values()] == [None, None, None]
        engine.spawn('ball', urdf('ball.urdf'), (-7.0, 6.0, 0.5, 0.0), namespace='ball')
        engine.spawn('ball2', urdf('ball.urdf'), (-7.0, 3.0, 0.5, 0.0), namespace='ball2')
        assert engine.models['ball'].script is not None       # the first one that is a ball
        assert engine.models['ball2'].script is None
    finally:
        engine.close()


def test_legs_given_by_hand_are_played_and_checked_against_the_bounds():
    engine = world('{"legs": [{"show": [1, 2], "stay": 2}, '
                   '{"move": [4, 6], "speed": 1, "stay": 1}, {"hide": 3}]}')
    try:
        engine.run_for(4.5)                                  # 2.5 s of the 5 s way
        assert engine.models['ball'].pose()[0] == pytest.approx((2.5, 4.0, 0.5), abs=0.011)
        (vx, vy, _), _ = engine.models['ball'].twist()
        assert math.hypot(vx, vy) == pytest.approx(1.0)
        engine.run_for(4.0)
        assert engine.models['ball'].hidden and engine.models['ball'].pose()[0][2] == -3.0
    finally:
        engine.close()
    with pytest.raises(ValueError) as err:
        Engine(bounds=BOUNDS, settings={'ball_script': '{"legs": [{"show": [12, 0]}]}'})
    assert str(err.value) == ('ball script: leg 1 {"show": [12.0, 0.0], "stay": 0.0}: the place '
                              '(12, 0) is outside the arena x -8.8..8.8, y -8.8..8.8')


def test_a_world_with_no_room_leaves_the_ball_to_the_nodes():
    engine = Engine(registry=CORES, bounds=(0, 1, 0, 1), log=RecordingLog(),
                    settings={'ball_script': {'seed': 2}})
    try:
        engine.spawn('ball', urdf('ball.urdf'), (0.5, 0.5, 0.5, 0.0), namespace='ball')
        assert engine.models['ball'].script is None
        assert any(level == 'error' and 'leaves no room' in line and 'is left to the nodes'
                   in line for level, line in engine.log.lines)
        engine.models['ball'].set_pose((0.2, 0.2, 0.5))
        assert engine.models['ball'].placed == 1
    finally:
        engine.close()


def test_in_an_sdf_world_the_course_keeps_within_its_walls_and_clear_of_its_objects():
    from exp_assignment2.sim import sdf
    here = os.path.dirname(os.path.abspath(__file__))
    found = sdf.read_world(os.path.join(os.path.dirname(here), 'fixtures', 'student_pkg',
                                        'worlds', 'small.world'))
    engine = Engine(registry=CORES, log=RecordingLog(), settings={'ball_script': {'seed': 8}})
    try:
        for model in found.models:            # walls at y = +-6, a post, a meshed barrier
            engine.spawn(model.name, model.urdf, model.pose)
        engine.spawn('ball', urdf('ball.urdf'), (1.5, 0.0, 0.5, 0.0), namespace='ball')
        places = [leg.place for leg in engine.scripted_ball.script.legs if leg.place]
        assert len(places) >= 5
        for x, y in places:
            assert abs(x) <= 4.6 and abs(y) <= 4.6, (x, y)       # 1 m inside the walls' box
            assert math.hypot(x + 3.0, y - 3.0) >= 1.5           # the post at (-3, 3)
            assert not (-7.0 <= x <= -1.0 and -5.1 <= y <= -2.4), (x, y)   # the barrier
    finally:
        engine.close()

"""bench/simulator_cost.py: what the simulator's cost went with, read from its own
log in a grading's run folder (frames drawn, in the course camera's pixels; the
nodes on /clock; the models) and the least-squares line through the runs."""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), 'bench'))
import simulator_cost  # noqa: E402

LOG = '''[rosout][INFO] 1: simulator: 24 models, step 0.0100 s, real_time_factor 1
[rospy.internal][INFO] 2: topic[/clock] adding connection to [/a], count 0
[rospy.internal][INFO] 2: topic[/clock] adding connection to [/b], count 1
[rospy.internal][INFO] 2: topic[/clock] removing connection to /a
[rospy.internal][INFO] 2: topic[/clock] adding connection to [/c], count 1
[rosout][INFO] 3: camera camera1: %d frames, %d of them of a still scene (not drawn again)%s
'''


def grading(tmp_path, label, frames, still, size=''):
    log = tmp_path / 'runs' / label / 'work' / 'ros_home' / 'log' / 'x' / 'gazebo-1.log'
    log.parent.mkdir(parents=True)
    log.write_text(LOG % (frames, still, size))
    command = '/usr/bin/python3 simulator.py __log:=/tmp/g/runs/%s/work/ros_home/log/x/' \
        'gazebo-1.log' % label
    return {'label': label, 'cpu_s': {'simulator': 0.0}, 'truth': {'sim_time': 100.0,
                                                                    'simulator': command}}


def test_a_run_s_world_is_read_from_its_simulator_s_log(tmp_path):
    run = grading(tmp_path, 'a', 3000, 1000)
    facts = simulator_cost.world_facts(simulator_cost.simulator_log(str(tmp_path), run))
    assert facts == {'models': 24, 'drawn': 2000, 'still': 1000, 'clock': 2}
    small = grading(tmp_path, 'b', 1500, 0, ', 400 x 400')     # a quarter of the pixels
    facts = simulator_cost.world_facts(simulator_cost.simulator_log(str(tmp_path), small))
    assert facts['drawn'] == pytest.approx(375)


def test_the_line_through_the_runs_says_what_a_frame_costs(tmp_path):
    runs = []
    for i, (frames, cores) in enumerate([(0, 0.12), (1500, 0.23), (3000, 0.34),
                                         (3000, 0.34), (600, 0.16)]):
        run = grading(tmp_path, 'r%d' % i, frames, 0)
        run['cpu_s']['simulator'] = cores * 100.0
        runs.append(run)
    found = simulator_cost.rows(str(tmp_path), runs)
    assert [r[2] for r in found] == [0, 15, 30, 30, 6]
    line = simulator_cost.fit(found)
    assert line is None         # every run had 2 nodes on /clock: that one is not told apart
    runs[0]['label'] = 'r0'
    (tmp_path / 'runs' / 'r0' / 'work' / 'ros_home' / 'log' / 'x' / 'gazebo-1.log').write_text(
        LOG.replace('adding connection to [/c]', 'adding connection to [/c]\n'
                    '[x] topic[/clock] adding connection to [/d]') % (0, 0, ''))
    a, b, c = simulator_cost.fit(simulator_cost.rows(str(tmp_path), runs))
    assert b == pytest.approx(0.22 / 30, abs=1e-3)

"""The grader end to end on how a student says to start the dog
(test/start_fixtures.py, graded with the rest of the fixture folder by
test/grading_run.py): a README that goes into launch/ and mistypes a launch
file, and a start script whose own roslaunch must come before the node its
terminal opens."""
import os

import pytest

pytestmark = pytest.mark.xdist_group('grader')


def test_a_readmes_cd_and_typo_and_a_start_scripts_timing(graded):
    """test/start_fixtures.py: `cd launch` then `roslaunch gazebo_world.launch`
    runs from launch/; a mistyped launch file runs the one close to it, said;
    a start script's own roslaunch starts before the node its terminal opens
    (which needs the launch file's node up: in text order it raised)."""
    typo = graded['runs']['readme_cd_typo']
    assert typo['verdict'] == 'passed', (typo['reason'], typo['notes'])
    assert typo['commands'] == ['roslaunch gazebo_world.launch',
                                'roslaunch exp_assignment2 dog_behavior.launch']
    assert typo['notes'] == ["`roslaunch exp_assignment2 dog_beaviour.launch`: ran "
                             "`dog_behavior.launch` for the README's `dog_beaviour.launch`"]
    started = {e['index']: e for e in typo['events'] if e.get('event') == 'started'}
    assert started[0]['cwd'] == 'launch' and started[1]['at'] >= 5.0
    timing = graded['runs']['script_timing']
    assert timing['verdict'] == 'passed', (timing['reason'], timing['notes'])
    assert timing['commands'] == ['rosrun exp_assignment2 dog.py',
                                  'roslaunch --wait exp_assignment2 gazebo_world.launch']
    started = {e['index']: e['at'] for e in timing['events'] if e.get('event') == 'started'}
    assert started[1] < started[0], started       # the script's own line first
    with open(os.path.join(graded['out'], 'pages', 'script_timing.html')) as f:
        assert '<td>a build step</td>' in f.read()     # its README's catkin_make

"""The grader judges the student's robot, head and ball by their roles, and
gives a node what ROS desktop-full had: two submissions of the fixture folder
graded once a session (test/grading_run.py), read as a teacher reads them."""
import os

import pytest

pytestmark = pytest.mark.xdist_group('grader')


def test_a_renamed_robot_head_and_ball_are_judged_by_their_roles(graded):
    """robot2 in its own namespace, its head on camera_joint moved by a
    camera_position_controller, the ball called toy: the dog plays as the one
    that works does, and passes as it; the page names what it judged and why,
    and its camera pictures are robot2's own."""
    run = graded['runs']['renamed']
    assert run['verdict'] == 'passed', (run['reason'], run.get('checks'))
    assert {k: run['roles'][k]['name'] for k in ('robot', 'head', 'camera', 'ball')} == {
        'robot': 'robot2', 'head': 'camera_joint', 'camera': 'robot2/camera1', 'ball': 'toy'}
    assert run['roles']['namespace'] == 'robot2'
    checks = {c['name']: c for c in run['checks']}
    assert checks['head turns both ways at the ball']['value'] >= 0.5
    assert checks['head turns both ways at the ball']['detail'].startswith('camera_joint: ')
    for page in ('pages', 'feedback'):
        with open(os.path.join(graded['out'], page, 'renamed.html')) as f:
            text = f.read()
        assert '<code>camera_joint</code>, the joint that turns camera <code>camera1</code>' \
            in text, page
        assert '<code>robot2</code>: driven through /robot2/cmd_vel' in text, page
    frames = os.listdir(os.path.join(graded['out'], 'runs', 'renamed', 'record', 'frames'))
    assert frames and all(f.startswith('robot2_camera1_') for f in frames)
    assert os.path.exists(os.path.join(graded['out'], 'pages', 'img',
                                       'renamed_closest_approach.jpg'))


def test_what_ros_desktop_full_had_is_there(graded):
    """A node importing actionlib_tutorials.msg (every desktop-full install had
    it) runs as on the student's machine: no error, the dog plays."""
    run = graded['runs']['tutorials']
    assert run['verdict'] == 'passed', (run['reason'], run.get('errors'))
    assert run['error_count'] == 0

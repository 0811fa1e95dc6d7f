"""The simulator node's parameters: one line naming a refused one, its value
and what is accepted; the camera's size between what the dog's vision needs
and what OpenGL draws."""
import math

import pytest

from exp_assignment2.sim.limits import (FALLBACK_MAX_SIZE, MIN_CAMERA_SIZE, ParameterError,
                                        check_node_params, gl_max_image_size)

LAUNCH = {'real_time_factor': 1.0, 'time_step': 0.01, 'renderer': 'gl', 'paused': False,
          'cmd_timeout': 0.5, 'camera_width': 800, 'camera_height': 800, 'camera_rate': 30,
          'camera_hfov': 80, 'wait_for_camera': True, 'start_timeout': 30.0, 'hidden': [],
          'urdf_dir': None}


def check(max_size=lambda: 16384, **changes):
    return check_node_params(dict(LAUNCH, **changes), max_size)


def test_what_the_launch_files_pass_is_accepted():
    assert check() == dict(LAUNCH, camera_rate=30.0, camera_hfov=80.0)
    assert check(camera_width=None, camera_height=None, camera_rate=None, camera_hfov=None,
                 cmd_timeout=None)['camera_width'] is None
    assert check(camera_width='', camera_height='', camera_rate='')['camera_width'] == ''
    assert check(robot_ns='robot2')['robot_ns'] == 'robot2', 'other keys pass through'
    # gazebo_ros' own, as empty_world.launch sets them
    assert check(pub_clock_frequency=100, enable_ros_network=True)['pub_clock_frequency'] == 100.0



@pytest.mark.parametrize('name,value,shown', [
    ('camera_width', 1, '1'), ('camera_width', 100000, '100000'),
    ('camera_width', float('nan'), 'nan'), ('camera_width', 'abc', 'abc'),
    ('camera_width', 800.5, '800.5'), ('camera_width', True, 'True'),
    ('camera_height', 239, '239'), ('camera_rate', 0, '0'), ('camera_rate', 101, '101'),
    ('camera_hfov', 180, '180'), ('real_time_factor', -1, '-1'),
    ('real_time_factor', float('inf'), 'inf'), ('time_step', 0, '0'),
    ('renderer', 'bogus', 'bogus'), ('paused', 'yes', 'yes'), ('cmd_timeout', -0.1, '-0.1'),
    ('start_timeout', 0, '0'), ('max_real_time_factor', -1, '-1'),
    ('max_real_time_factor', 'fast', 'fast'), ('pub_clock_frequency', -1, '-1'),
    ('pub_clock_frequency', float('nan'), 'nan'), ('enable_ros_network', 'no', 'no')])
def test_a_bad_value_is_one_line_naming_it_and_what_is_accepted(name, value, shown):
    with pytest.raises(ParameterError) as refused:
        check(**{name: value})
    line = str(refused.value)
    assert line.startswith('~%s = %s is refused; accepted: ' % (name, shown)), line
    assert '\n' not in line and len(line) < 300


def test_the_camera_size_is_bounded_by_vision_and_by_what_opengl_draws():
    assert check(camera_width=MIN_CAMERA_SIZE)['camera_width'] == MIN_CAMERA_SIZE
    assert check(camera_width=4096.0)['camera_width'] == 4096
    with pytest.raises(ParameterError, match=r'in \[240, 2048\].*OpenGL draws'):
        check(lambda: 2048, camera_width=4096)
    with pytest.raises(ParameterError, match=r'in \[240, %d\]' % FALLBACK_MAX_SIZE):
        check(lambda: None, camera_width=8000)


def test_the_renderer_is_asked_at_most_once_and_only_for_a_camera_size():
    asked = []

    def max_size():
        asked.append(1)
        return 16384
    check(max_size)
    assert asked == [1]
    check(max_size, camera_width=None, camera_height=None)
    assert asked == [1]


def test_opengl_here_draws_at_least_the_default_camera():
    size = gl_max_image_size()
    if size is None:
        pytest.skip('no OpenGL context on this machine')
    assert size >= 800


def detected_at(width, distance):
    """Is the ball seen ``distance`` m ahead of the dog in a ``width`` px image?"""
    import gl_scene as render
    from exp_assignment2.vision import BallDetector
    scene = render.Scene()
    try:
        cam = scene.pose_robot(yaw=-math.pi / 4)    # from the spawn point across the arena
        gl = render.make_renderer(scene.reader.description, width, width)
        try:
            scene.ball_ahead(cam, distance)
            image = gl.render(scene.reader.read_poses(), cam, render.HFOV, render.NEAR,
                              render.FAR).copy()
        finally:
            gl.close()
        return BallDetector().detect(image) is not None
    finally:
        render.p.disconnect(scene.client)


def test_at_the_smallest_size_the_dog_sees_the_ball_as_far_as_at_800_px():
    assert detected_at(800, 18.0)
    assert detected_at(MIN_CAMERA_SIZE, 18.0)
    assert not detected_at(200, 18.0), 'a smaller image would do: lower MIN_CAMERA_SIZE'

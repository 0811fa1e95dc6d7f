"""What gzclient shows, read without ROS: the viewer's frames and display, the
frame rate the grader asks of a display nobody watches, and Gazebo's window's
pictures as they come."""
from types import SimpleNamespace

from exp_assignment2.launch_surface import viewer


def test_viewer_frames_and_display():
    def pose(x, w=1.0):
        return SimpleNamespace(position=SimpleNamespace(x=x, y=0.0, z=0.0),
                               orientation=SimpleNamespace(x=0.0, y=0.0, z=0.0, w=w))
    out = viewer.frames(['robot', 'robot::link_chassis', '', 'bad'],
                        [pose(1), pose(2), pose(3), pose(float('nan'))])
    assert [f for f, _ in out] == ['gazebo/robot', 'gazebo/robot/link_chassis']
    assert viewer.display_of({}) is None and viewer.display_of({'DISPLAY': ':1'}) == ':1'
    assert viewer.display_of({'WAYLAND_DISPLAY': 'wayland-0'}) == 'wayland-0'


def test_a_viewer_nobody_watches_is_known_by_the_rate_asked():
    """The grader's display is captured once a wall second: it asks its viewers
    for two frames a second, and gzclient shows the simulator's pictures of the
    world there instead of opening rviz."""
    from exp_assignment2.launch_surface.viewer import FRAME_RATE_ENV, frame_rate
    assert frame_rate({}) is None
    assert frame_rate({FRAME_RATE_ENV: '2'}) == 2.0
    for bad in ('nan', '0', '-3', '500', 'fast'):
        assert frame_rate({FRAME_RATE_ENV: bad}) is None, bad


def test_gazebo_s_window_reads_the_pictures_as_they_come():
    from sensor_msgs.msg import Image
    from exp_assignment2.launch_surface.gui_window import pixels
    rows = bytes(range(2 * 8)) * 3         # 3 rows of 2 pixels (6 bytes), 2 of padding each
    image = Image(height=3, width=2, step=8, encoding='bgr8', data=rows)
    got = pixels(image)
    assert got.shape == (3, 2, 3) and got[1, 1].tolist() == [11, 12, 13]
    assert pixels(Image(height=3, width=2, step=6, encoding='rgb8', data=rows)) is None
    assert pixels(Image(height=30, width=2, step=6, encoding='bgr8', data=rows)) is None

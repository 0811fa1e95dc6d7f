"""Gazebo's grid on an SDF world's ground plane: a GUI visual, in the user camera's
view only (no ROS, no catkin build; skipped where there is no EGL context)."""
import numpy as np

from gl_scene import FAR, H, HFOV, NEAR, make_renderer, scene  # noqa: F401
from exp_assignment2.sim.gl.scene import SceneReader, drawable
from exp_assignment2.sim.model import GUI_GRID
from test_render_gl import looking_down


def grid_line_pixels(img):
    """Pixels along world y, in the image's middle row, darker than the floor."""
    row = img[H // 2, :, 1].astype(int)
    return int((row < 0.7 * np.median(row)).sum())


def test_gazebos_grid_is_seen_by_its_user_camera_only(scene):
    """An SDF world's ground plane carries Gazebo's GUI grid: gzclient's view
    shows it, a camera sensor's images do not (rendering::Grid is a GUI visual)."""
    reader = SceneReader([drawable(scene.arena, scene.urdf['arena'], GUI_GRID, 'arena')],
                         scene.client)
    gl = make_renderer(reader.description)
    try:
        cam = looking_down(0.5, 0.5, 2.0)
        sensor = gl.render(reader.read_poses(), cam, HFOV, NEAR, FAR).copy()
        user = gl.render(reader.read_poses(), cam, HFOV, NEAR, FAR, gui=True).copy()
    finally:
        gl.close()
    assert grid_line_pixels(sensor) == 0
    assert np.ptp(sensor[H // 2, :, 1]) <= 2          # one lit grey, no lines
    assert grid_line_pixels(user) >= 6                # two lines of 3 px or more

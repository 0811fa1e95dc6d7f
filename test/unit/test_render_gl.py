"""The package's OpenGL renderer (sim/gl/), on its own and against
pybullet's TinyRenderer at the same camera pose. No ROS, no catkin build. Tests that need moderngl and an EGL context are
skipped, with the renderer's one-line reason, where those are missing. The
IoU / centre numbers of the TinyRenderer comparison are printed (shown even
without ``-s``).
"""
import math
import threading

import numpy as np
import pytest

from gl_scene import (FAR, H, HFOV, NEAR, W, focal, gl, make_renderer,  # noqa: F401
                      mesh_world, one_body_world, p, render, scene, tiny_image)
from exp_assignment2.sim.gl.scene import GLRenderer, view_projection
from exp_assignment2.sim.rotations import rpy_matrix
from exp_assignment2.vision import BallDetector


def ball_masks(gl_img, tiny_img):
    det = BallDetector()
    g = det.detect(gl_img)
    gm = det.last_mask > 0
    t = det.detect(tiny_img)
    tm = det.last_mask > 0
    return g, gm, t, tm


MIN_IOU = 0.9
# name: (robot yaw, head angle, ball distance ahead (m), ball lateral offset (m))
POSES = {
    'near': (math.pi, 0.0, 1.5, 0.0),
    # Facing -y: 8 m ahead stays inside the walls. At ~12 px radius what is
    # left between the two is TinyRenderer's coarse sphere (a hull whose
    # outline has ~7 % less area than the sphere's, which GL's matches:
    # test_far_ball_outline_is_the_exact_projection): IoU 0.935 to 0.959 over
    # sub-pixel ball offsets, 3 to 10 m all >= 0.92. Without the pixel-centre
    # correction (tiny_image) it was 0.885 here, >= 0.9 only up to ~6 m.
    'far': (-math.pi / 2, 0.0, 8.0, 0.0),
    'edge': (math.pi, 0.0, 2.5, 2.0),          # centre ~10 px from the left edge
    'head_turned': (math.pi, 0.6, 2.5, 0.0),
}


@pytest.mark.parametrize('name', sorted(POSES))
def test_same_ball_as_tiny_renderer(scene, gl, capsys, name):
    yaw, head, dist, lateral = POSES[name]
    cam = scene.pose_robot(yaw, head)
    scene.ball_ahead(cam, dist, lateral)
    g, gm, t, tm = ball_masks(render(gl, scene, cam), scene.tiny(cam))
    assert g is not None and t is not None
    iou = np.logical_and(gm, tm).sum() / float(np.logical_or(gm, tm).sum())
    centre = math.hypot(g.x - t.x, g.y - t.y)
    centroid = math.hypot(g.cx - t.cx, g.cy - t.cy)
    with capsys.disabled():
        print('\n[gl vs tiny %s] IoU %.3f  centre %.2f px  centroid %.2f px  '
              'radius gl %.1f tiny %.1f px' % (name, iou, centre, centroid, g.radius, t.radius))
    scene.pose_robot()
    assert iou >= MIN_IOU
    assert centre <= 2.0 and centroid <= 2.0


def coloured_pixels(bgr, channel):
    """Mask of the pixels where BGR ``channel`` stands out of the other two."""
    others = np.delete(bgr, channel, axis=2).max(axis=2)
    return (bgr[:, :, channel].astype(int) - others) > 40


def test_far_ball_outline_is_the_exact_projection(scene, gl, capsys):
    """At 8 m GL's ball covers the area and centroid of the exact sphere's
    projection; TinyRenderer's is smaller and, as pybullet sets it up
    ('tiny raw'), offset by half a pixel."""
    cam = scene.pose_robot(-math.pi / 2)
    scene.ball_ahead(cam, 8.0)
    ball = np.array(p.getBasePositionAndOrientation(scene.ball, physicsClientId=scene.client)[0])
    local = (ball - cam[0]).dot(cam[1])
    f, dist = focal(W), np.linalg.norm(local)
    radius = f * 0.5 / math.sqrt(dist ** 2 - 0.25)     # on-axis sphere: a disc
    u, v = W / 2.0 - f * local[1] / local[0] - 0.5, H / 2.0 - f * local[2] / local[0] - 0.5
    stats = {}
    images = (('gl', render(gl, scene, cam)), ('tiny', scene.tiny(cam)),
              ('tiny raw', scene.tiny(cam, pixel_centres=False)))
    for label, img in images:
        ys, xs = np.nonzero(coloured_pixels(img, 1))
        stats[label] = (len(xs) / (math.pi * radius ** 2), xs.mean() - u, ys.mean() - v)
    with capsys.disabled():
        print('\n[far ball vs exact projection] area ratio, centroid dx, dy (px): ' + '; '.join(
            '%s %.3f %+.2f %+.2f' % ((k,) + stats[k]) for k, _ in images))
    scene.pose_robot()
    area, dx, dy = stats['gl']
    assert abs(area - 1) < 0.04 and abs(dx) < 0.25 and abs(dy) < 0.25
    assert max(abs(d) for d in stats['tiny'][1:]) < 0.25      # only its hull differs
    assert min(abs(d) for d in stats['tiny raw'][1:]) > 0.4


BOX_URDF = '''<?xml version="1.0"?>
<robot name="box"><link name="box"><visual><geometry><box size="1 1 1"/></geometry>
  <material name="red"><color rgba="0.9 0.1 0.1 1"/></material></visual></link>
  <gazebo><static>true</static></gazebo></robot>
'''


@pytest.mark.parametrize('size', [(W, H), (400, 240)])
def test_tiny_renderer_at_pixel_centres_draws_boxes_as_gl(tmp_path, size):
    """Boxes have no tessellation to differ by: TinyRenderer, as pybullet sets
    it up, draws a box half a pixel right of and above GL; moved back half a
    pixel (tiny_image's pixel_centres), it covers GL's pixels but for a rare
    tie on an edge (~3 % of them differ before)."""
    (tmp_path / 'box.urdf').write_text(BOX_URDF)
    client, reader = one_body_world(str(tmp_path / 'box.urdf'), [0, 0, 0])
    width, height = size
    rng = np.random.default_rng(3)
    shifts = []   # raw TinyRenderer's centroid minus GL's, (dx, dy) px
    try:
        with make_renderer(reader.description, width, height, background=(1, 1, 1)) as gl:
            for _ in range(8):
                cam = (np.array([-4.0, 0.0, 0.0]) + rng.uniform(-0.5, 0.5, 3),
                       rpy_matrix(*rng.uniform(-0.3, 0.3, 3)))
                red = coloured_pixels(gl.render(reader.read_poses(), cam, HFOV, NEAR, FAR), 2)
                fixed, raw = (coloured_pixels(tiny_image(client, cam, width, height, c), 2)
                              for c in (True, False))
                assert red.sum() > 2000
                assert (fixed ^ red).sum() <= 0.002 * red.sum()
                assert (raw ^ red).sum() > 0.01 * red.sum()
                (ry, rx), (gy, gx) = np.nonzero(raw), np.nonzero(red)
                shifts.append((rx.mean() - gx.mean(), ry.mean() - gy.mean()))
    finally:
        p.disconnect(client)
    # each view's shift is whole pixels per edge; over views it averages out
    np.testing.assert_allclose(np.mean(shifts, axis=0), (0.5, -0.5), atol=0.15)


def test_hidden_body_is_not_drawn(scene, gl):
    cam = scene.pose_robot()
    scene.ball_ahead(cam, 2.0)
    det = BallDetector()
    assert det.detect(render(gl, scene, cam)) is not None
    assert det.detect(render(gl, scene, cam, hidden=['ball'])) is None
    assert det.detect(render(gl, scene, cam, hidden=[scene.ball])) is None   # by body id
    assert det.detect(render(gl, scene, cam)) is not None


def test_image_layout_and_orientation(scene):
    cam = scene.pose_robot(-math.pi / 2)
    scene.ball_ahead(cam, 3.0, 1.0)
    gl = make_renderer(scene.reader.description, 400, 240)
    try:
        img = gl.render(scene.reader.read_poses(), cam, HFOV, NEAR, FAR)
        assert img.shape == (240, 400, 3) and img.dtype == np.uint8
        assert img.flags['C_CONTIGUOUS']
        # row 0 is the top: sky (BGR of (0.7, 0.7, 0.8)) above, floor grey below
        np.testing.assert_array_equal(img[0, 5], [204, 178, 178])
        bottom = img[-30:].reshape(-1, 3).astype(int)   # grey floor (and a grid line)
        assert np.abs(bottom[:, 0] - bottom[:, 2]).max() < 3 and np.median(bottom[:, 1]) > 120
        out = np.zeros_like(img)
        assert gl.render(scene.reader.read_poses(), cam, HFOV, NEAR, FAR, out=out) is out
        np.testing.assert_array_equal(out, img)
        ball = BallDetector().detect(img)
        tiny = BallDetector().detect(scene.tiny(cam, 400, 240))
        # non-square: the same place (centroids; enclosing circles of the faceted
        # TinyRenderer ball wobble by up to ~2 px)
        assert math.hypot(ball.cx - tiny.cx, ball.cy - tiny.cy) <= 1.5
    finally:
        scene.pose_robot()
        gl.close()
        gl.close()   # closing twice is harmless


def looking_down(x, y, z):
    """A camera at (x, y, z) looking straight down, image up = world +x."""
    rot = np.array([[0, 0, 1], [0, 1, 0], [-1, 0, 0]], float)   # columns: ahead, left, up
    return np.array([x, y, z]), rot


def test_floor_grid_is_visible(scene, gl):
    cam = looking_down(0.5, 0.5, 2.0)            # lines at x, y = -1, 0, 1, 2 in view
    img = render(gl, scene, cam)
    row = img[H // 2, :, 1].astype(int)          # along world y
    floor = np.median(row)
    dark = row < 0.7 * floor
    runs = np.flatnonzero(np.diff(np.r_[0, dark.astype(int), 0]))
    starts, ends = runs[::2], runs[1::2]
    widths = ends - starts
    # two full lines (y = 0 and y = 1) 1 m apart, each 0.06 m wide, at 2 m away
    full = widths >= 3
    assert full.sum() >= 2
    centres = (starts + ends)[full] / 2.0
    px_per_m = focal(W) / 2.0
    assert np.diff(centres) == pytest.approx(px_per_m, abs=2)
    assert widths[full] == pytest.approx(0.06 * px_per_m, abs=2)
    assert 150 < floor < 230                      # light floor between the lines
    assert row[dark].min() < 0.5 * floor          # dark grey lines


def test_sphere_is_brighter_on_its_lit_side(scene, gl):
    cam = scene.pose_robot(-math.pi / 2)           # facing -y: nothing but the ball ahead
    scene.ball_ahead(cam, 2.0)
    pos, rot = cam
    centre = np.array(p.getBasePositionAndOrientation(scene.ball,
                                                      physicsClientId=scene.client)[0])
    toward_cam = (pos - centre) / np.linalg.norm(pos - centre)
    light = gl.light_dir - gl.light_dir.dot(toward_cam) * toward_cam   # across the view
    light /= np.linalg.norm(light)
    img = render(gl, scene, cam)
    vp = view_projection(np.r_[np.c_[rot, pos], [[0, 0, 0, 1]]], W, H, HFOV, NEAR, FAR)

    def pixel(point):
        c = vp.dot(np.r_[point, 1.0])
        return int((c[0] / c[3] + 1) / 2 * W), int((c[1] / c[3] + 1) / 2 * H)

    lit, far = [centre + 0.5 * (0.7 * s * light + 0.714 * toward_cam) for s in (1, -1)]
    (ul, vl), (uf, vf) = pixel(lit), pixel(far)
    assert int(img[vl, ul, 1]) > int(img[vf, uf, 1]) + 40
    assert img[vl, ul, 1] > 150 and img[vf, uf, 1] > 60   # ambient still lights the far side
    scene.pose_robot()


def test_mesh_models_in_their_colour_where_expected(tmp_path):
    client, reader = mesh_world(tmp_path)
    try:
        gl = make_renderer(reader.description, 320, 320, background=(1, 1, 1))
        cam = np.eye(4)
        cam[:3, 3] = (-3.0, 0.0, 1.0)                      # looking along +x at the cubes
        with gl:
            img = gl.render(reader.read_poses(), cam, HFOV, NEAR, FAR)
        vp = view_projection(cam, 320, 320, HFOV, NEAR, FAR)
        corners = np.array([(x, y, z) for x in (-.2, .2) for y in (-.2, .2) for z in (-.2, .2)])
        # red: the OBJ cube at the URDF base frame (0, 0, 1), whatever the
        # inertial frame; blue: the STL cube on the child link 1 m to its left
        for (hi, lo), centre in (((2, 0), (0, 0, 1)), ((0, 2), (0, 1, 1))):   # BGR indices
            ys, xs = np.nonzero((img[:, :, hi].astype(int) - img[:, :, lo]) > 60)
            clip = vp.dot(np.c_[corners + centre, np.ones(8)].T)
            u = (clip[0] / clip[3] + 1) / 2 * 320
            v = (clip[1] / clip[3] + 1) / 2 * 320
            # the silhouette's pixels span the projected corners' box
            assert xs.min() == pytest.approx(u.min(), abs=1.0)
            assert xs.max() + 1 == pytest.approx(u.max(), abs=1.0)
            assert ys.min() == pytest.approx(v.min(), abs=1.0)
            assert ys.max() + 1 == pytest.approx(v.max(), abs=1.0)
    finally:
        p.disconnect(client)


def test_geometry_is_uploaded_once(scene, gl, monkeypatch):
    import moderngl
    calls = []
    for cls, names in ((moderngl.Context, ('buffer', 'texture', 'vertex_array', 'program',
                                            'renderbuffer', 'depth_renderbuffer',
                                            'framebuffer', 'simple_vertex_array')),
                       (moderngl.Buffer, ('write', 'orphan'))):
        for name in names:
            orig = getattr(cls, name)
            monkeypatch.setattr(cls, name, lambda *a, _n=name, _o=orig, **k:
                                calls.append(_n) or _o(*a, **k))
    assert gl.vbo.size == scene.reader.description.vertices.nbytes
    cam = scene.pose_robot()
    for head in np.linspace(-0.5, 0.5, 10):       # poses change, geometry does not
        scene.pose_robot(math.pi, head)
        render(gl, scene, cam)
    scene.pose_robot()
    assert calls == []


def test_renders_on_another_thread_than_the_simulator(scene, gl):
    cam = scene.pose_robot()
    scene.ball_ahead(cam, 2.0)
    poses = scene.reader.read_poses()              # the simulator thread's snapshot
    result = {}

    def worker():
        try:
            with GLRenderer(scene.reader.description, W, H) as r:
                result['image'] = r.render(poses, cam, HFOV, NEAR, FAR).copy()
            gl.render(poses, cam)                  # not this thread's context
        except RuntimeError as exc:
            result['error'] = str(exc)

    t = threading.Thread(target=worker)
    t.start()
    t.join()
    np.testing.assert_array_equal(result['image'], gl.render(poses, cam, HFOV, NEAR, FAR))
    assert 'thread other than' in result['error']


def test_unavailable_gl_is_one_readable_runtime_error(scene, monkeypatch):
    import sys
    import moderngl

    def no_egl(**kw):
        raise Exception('eglInitialize failed\n(no display)')

    monkeypatch.setattr(moderngl, 'create_standalone_context', no_egl)
    with pytest.raises(RuntimeError) as err:
        GLRenderer(scene.reader.description, 64, 64)
    assert '\n' not in str(err.value) and str(err.value).startswith('gl renderer unavailable')
    monkeypatch.setitem(sys.modules, 'moderngl', None)   # not installed
    with pytest.raises(RuntimeError) as err:
        GLRenderer(scene.reader.description, 64, 64)
    assert '\n' not in str(err.value) and 'moderngl' in str(err.value)

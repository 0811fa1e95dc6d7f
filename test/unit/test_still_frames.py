"""A camera's frame whose scene did not change is not drawn or encoded again,
and nothing a student's code sees changes: the frames of a still scene and
of a moving one are the same, pixel for pixel and JPEG byte for byte, with
the change and without it (every frame drawn: gl's STILL below zero); a
still frame goes out with its own stamp, the last frame's bytes reused. No
master: the camera plugin's publishers are stand-ins."""
import numpy as np
import pytest
from sensor_msgs.msg import CameraInfo

from exp_assignment2.sim.camera import CameraSpec
from exp_assignment2.sim.gl import backend as gl_backend
from exp_assignment2.sim.offline import make_engine
from exp_assignment2.sim.plugins.camera import CameraPlugin
from exp_assignment2.sim.plugins.frame_worker import FrameWorker
from exp_assignment2.vision import encode_jpeg


class Frames(object):
    """Stands in for a camera: each frame's pixels, JPEG bytes and whether it was still."""

    def __init__(self):
        self.pixels, self.jpegs, self.still = [], [], []

    def publish(self, stamp, bgr, same=False):
        self.pixels.append(bgr.copy())
        self.jpegs.append(encode_jpeg(bgr, 80))
        self.still.append(same)


def frames(monkeypatch, still, moves):
    """Five frames of the robot's camera; ``moves``: the ball moves between
    them; ``still``: gl's tolerance (below zero: every frame drawn)."""
    monkeypatch.setattr(gl_backend, 'STILL', still)
    engine = make_engine()
    engine.step()
    worker, camera = FrameWorker('gl', engine.handle), Frames()
    if worker.backend.name != 'gl':
        worker.close()
        engine.close()
        pytest.skip('no gl renderer here')
    spec = CameraSpec('robot', 'camera_link', width=200, height=200, hfov=80.0,
                      offset=(0.0, 0.0, 0.05, 0.0, 0.0, 0.0))
    ball = engine.models['ball']
    for stamp in range(5):
        if moves:
            x, y, z = ball.pose()[0]
            ball.set_pose((x + 0.2, y, z), (0.0, 0.0, 0.0, 1.0))
        worker.submit(camera, stamp, worker.backend.capture(spec))
    worker.close()
    engine.close()
    return camera


def test_a_still_scene_is_drawn_once_and_its_frames_are_the_ones_drawing_gives(monkeypatch):
    reused = frames(monkeypatch, gl_backend.STILL, moves=False)
    drawn = frames(monkeypatch, -1.0, moves=False)
    assert reused.still == [False, True, True, True, True]
    assert drawn.still == [False] * 5
    for a, b in zip(reused.pixels, drawn.pixels):
        assert np.array_equal(a, b)
    assert reused.jpegs == drawn.jpegs
    assert len(set(reused.jpegs)) == 1


def test_a_moving_scene_is_drawn_every_frame_as_without_the_change(monkeypatch):
    reused = frames(monkeypatch, gl_backend.STILL, moves=True)
    drawn = frames(monkeypatch, -1.0, moves=True)
    assert reused.still == drawn.still == [False] * 5
    for a, b in zip(reused.pixels, drawn.pixels):
        assert np.array_equal(a, b)
    assert reused.jpegs == drawn.jpegs
    assert len(set(reused.jpegs)) == 5          # the ball moved in every one


class Topic(object):
    def __init__(self, wanted=True):
        self.wanted, self.pub, self.sent = wanted, self, []

    def publish(self, message):
        self.sent.append(message)


def camera_plugin():
    """A CameraPlugin's publishing half, its topics stand-ins."""
    plugin = CameraPlugin.__new__(CameraPlugin)
    plugin.spec = CameraSpec('robot', 'camera_link', width=8, height=6)
    plugin.frame_id, plugin.sent, plugin.frames = 'camera_link', {}, [0, 0]
    plugin.jpeg, plugin.raw, plugin.info_pub = Topic(), Topic(), Topic()
    plugin.info = CameraInfo()
    plugin.engine = type('Engine', (), {'frame_drawn': lambda self, *args: None})()
    plugin.model = type('Model', (), {'name': 'robot'})()
    return plugin


def test_a_still_frame_goes_out_with_its_stamp_and_the_last_frame_s_bytes():
    import rospy
    plugin = camera_plugin()
    image = np.random.RandomState(1).randint(0, 255, (6, 8, 3)).astype(np.uint8)
    plugin.publish(rospy.Time(1), image)
    plugin.publish(rospy.Time(2), image, same=True)
    first, second = plugin.jpeg.sent
    assert second.data is first.data and second.header.stamp == rospy.Time(2)
    assert first.header.stamp == rospy.Time(1)
    raw1, raw2 = plugin.raw.sent
    assert raw2.data is raw1.data and raw2.header.stamp == rospy.Time(2) and \
        raw1.header.stamp == rospy.Time(1)
    assert raw1.encoding == 'rgb8' and (raw1.width, raw1.height) == (8, 6)
    assert [i.header.stamp for i in plugin.info_pub.sent] == [rospy.Time(1), rospy.Time(2)]
    plugin.raw.wanted = False          # only the compressed stream is watched...
    plugin.publish(rospy.Time(3), image[::-1].copy())
    plugin.raw.wanted = True           # ...and the raw one again, on a still frame
    plugin.publish(rospy.Time(4), image[::-1].copy(), same=True)
    assert plugin.raw.sent[-1].data == raw_bytes(image[::-1])
    assert plugin.jpeg.sent[-1].data is plugin.jpeg.sent[-2].data
    assert plugin.frames == [2, 2]


def raw_bytes(bgr):
    return np.ascontiguousarray(bgr[:, :, ::-1]).tobytes()

"""The camera's frame worker: frames are drawn on one thread and published on
another, in order, one hand-over slot at a time, a frame drawn while the one
before is published; gl that cannot start falls back to tiny with one line
(no master: rospy only logs)."""
import threading
import time

import numpy as np
import pytest

from exp_assignment2.sim.camera import CameraSpec
from exp_assignment2.sim.gl import backend as gl_backend
from exp_assignment2.sim.offline import make_engine
from exp_assignment2.sim.plugins.frame_worker import FrameWorker


class Recorder(object):
    """Stands in for a CameraPlugin: what the worker publishes."""

    def __init__(self):
        self.frames, self.threads = [], set()

    def publish(self, stamp, bgr, same=False):
        self.frames.append((stamp, bgr.shape, int(bgr.sum() > 0)))
        self.threads.add(threading.current_thread().name)


class Lines(object):
    """A host logger that keeps its lines."""

    def __init__(self):
        self.lines = []

    def info(self, text):
        pass

    def warn(self, text):
        self.lines.append(text)

    error = warn


@pytest.fixture
def engine():
    eng = make_engine(log=Lines())
    eng.step()
    yield eng
    eng.close()


def spec(size=64):
    return CameraSpec('robot', 'camera_link', width=size, height=size, hfov=80.0)


@pytest.mark.parametrize('kind', ['gl', 'tiny'])
def test_frames_are_published_on_the_worker_thread_in_order(engine, kind):
    worker, camera = FrameWorker(kind, engine.handle), Recorder()
    for stamp in range(5):
        worker.submit(camera, stamp, worker.backend.capture(spec()))
    worker.close()
    assert [f[0] for f in camera.frames] == list(range(5))
    assert all(shape == (64, 64, 3) and drawn for _, shape, drawn in camera.frames)
    assert camera.threads == {'camera publish'}
    assert worker.backend.name == kind


def test_gl_that_cannot_start_falls_back_to_tiny_with_one_line(engine, monkeypatch):
    lines = engine.log.lines
    del lines[:]             # what the spawns said
    monkeypatch.setattr(gl_backend.GLBackend, 'start', lambda self: (_ for _ in ()).throw(
        RuntimeError('gl renderer unavailable: no EGL here\nsecond line')))
    worker, camera = FrameWorker('gl', engine.handle), Recorder()
    worker.submit(camera, 0, worker.backend.capture(spec()))
    worker.close()
    assert worker.backend.name == 'tiny' and len(camera.frames) == 1
    assert lines == ['camera: renderer gl cannot start (gl renderer unavailable: no EGL here); '
                     'using tiny instead']


def test_the_hand_over_holds_one_frame_so_the_simulator_waits(engine, monkeypatch):
    worker, camera = FrameWorker('tiny', engine.handle), Recorder()
    release = threading.Event()
    slow = worker.backend.finish
    monkeypatch.setattr(worker.backend, 'finish', lambda job: (release.wait(5), slow(job))[1])
    job = worker.backend.capture(spec())
    worker.submit(camera, 0, job)           # taken by the worker, which blocks
    time.sleep(0.1)
    worker.submit(camera, 1, job)           # waits in the one slot
    third = threading.Thread(target=worker.submit, args=(camera, 2, job))
    third.start()
    time.sleep(0.2)
    assert third.is_alive(), 'a third frame queued instead of waiting'
    release.set()
    third.join(5)
    worker.close()
    assert [f[0] for f in camera.frames] == [0, 1, 2]


def test_a_hidden_ball_is_not_drawn_by_gl(engine):
    worker, camera, view = FrameWorker('gl', engine.handle), Recorder(), spec(200)
    seen = []
    camera.publish = lambda stamp, bgr, same=False: seen.append(int(np.count_nonzero(
        (bgr[:, :, 1] > 100) & (bgr[:, :, 0] < 60) & (bgr[:, :, 2] < 60))))
    worker.submit(camera, 0, worker.backend.capture(view))
    engine.models['ball'].hidden = True
    worker.submit(camera, 1, worker.backend.capture(view))
    worker.close()
    assert seen[0] > 1000 and seen[1] == 0


def test_a_frame_is_drawn_while_the_one_before_is_published(engine, monkeypatch):
    worker, camera = FrameWorker('tiny', engine.handle), Recorder()
    second_drawn = threading.Event()
    finish = worker.backend.finish

    def drawing(job):
        image = finish(job)
        if len(camera.frames) == 0 and drawing.calls == 1:
            second_drawn.set()
        drawing.calls += 1
        return image
    drawing.calls = 0
    monkeypatch.setattr(worker.backend, 'finish', drawing)
    publish = camera.publish

    def publishing(stamp, bgr, same=False):       # the first frame waits for the second's drawing
        if stamp == 0:
            assert second_drawn.wait(5), 'the second frame was not drawn meanwhile'
        publish(stamp, bgr)
    camera.publish = publishing
    job = worker.backend.capture(spec())
    for stamp in range(3):
        worker.submit(camera, stamp, job)
    worker.close()
    assert [f[0] for f in camera.frames] == [0, 1, 2]


def test_a_gl_frame_waiting_to_be_published_is_not_drawn_over(engine):
    worker, camera, view = FrameWorker('gl', engine.handle), Recorder(), spec(200)
    release, seen = threading.Event(), []

    def publishing(stamp, bgr, same=False):     # holds the first frame while two more are drawn
        if stamp == 0:
            release.wait(5)
        seen.append(int(np.count_nonzero(
            (bgr[:, :, 1] > 100) & (bgr[:, :, 0] < 60) & (bgr[:, :, 2] < 60))))
    camera.publish = publishing
    worker.submit(camera, 0, worker.backend.capture(view))
    engine.models['ball'].hidden = True
    worker.submit(camera, 1, worker.backend.capture(view))
    engine.models['ball'].hidden = False
    worker.submit(camera, 2, worker.backend.capture(view))   # drawn, then waits
    engine.models['ball'].hidden = True
    worker.submit(camera, 3, worker.backend.capture(view))   # drawn over the first?
    time.sleep(0.2)
    release.set()
    worker.close()
    assert seen[0] > 1000 and seen[1] == 0 and seen[2] > 1000 and seen[3] == 0


def test_a_transport_that_fails_to_publish_does_not_stop_the_camera(engine):
    """rospy raises on a topic its shutdown closed: the frame is dropped with
    a line, the next ones still go out, and closing does not wait."""
    worker, camera = FrameWorker('tiny', engine.handle), Recorder()
    publish = camera.publish

    def failing_once(stamp, bgr, same=False):
        if stamp == 1:
            raise KeyError('publish() to a closed topic')   # not a frame error
        publish(stamp, bgr)
    camera.publish = failing_once
    del engine.log.lines[:]
    job = worker.backend.capture(spec())
    for stamp in range(4):
        worker.submit(camera, stamp, job)
    start = time.monotonic()
    worker.close()
    assert time.monotonic() - start < 2.0
    assert [f[0] for f in camera.frames] == [0, 2, 3]
    assert engine.log.lines == ["camera: frame dropped: 'publish() to a closed topic'"]

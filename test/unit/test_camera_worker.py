"""The camera's frame worker: frames finish on another thread, in order, one
hand-over slot at a time; gl that cannot start falls back to tiny with one
line (no master: rospy only logs)."""
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

    def publish(self, stamp, bgr):
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
def test_frames_finish_on_the_worker_thread_in_order(engine, kind):
    worker, camera = FrameWorker(kind, engine.handle), Recorder()
    for stamp in range(5):
        worker.submit(camera, stamp, worker.backend.capture(spec()))
    worker.close()
    assert [f[0] for f in camera.frames] == list(range(5))
    assert all(shape == (64, 64, 3) and drawn for _, shape, drawn in camera.frames)
    assert camera.threads == {'camera'}
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
    worker, camera = FrameWorker('gl', engine.handle), Recorder()
    seen = []
    camera.publish = lambda stamp, bgr: seen.append(int(np.count_nonzero(
        (bgr[:, :, 1] > 100) & (bgr[:, :, 0] < 60) & (bgr[:, :, 2] < 60))))
    worker.submit(camera, 0, worker.backend.capture(spec(200)))
    engine.models['ball'].hidden = True
    worker.submit(camera, 1, worker.backend.capture(spec(200)))
    worker.close()
    assert seen[0] > 1000 and seen[1] == 0

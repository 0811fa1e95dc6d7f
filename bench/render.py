"""Rendering and vision figures of the benchmark, in-process (no ROS).

Every renderer draws the default dog world (config/world_dog.yaml) through
the simulator's own code: :mod:`exp_assignment2.sim.offline` builds the
engine and spawns the world's models, the camera backends render from the
robot's ``camera_link``.
"""
import statistics
import time

import cv2
import numpy as np

from exp_assignment2.sim.camera import CameraSpec
from exp_assignment2.sim.offline import make_engine
from exp_assignment2.vision import BallDetector, decode_jpeg, encode_jpeg, vision_scale

RENDERERS = ('gl', 'egl', 'tiny')


def camera(size):
    return CameraSpec('robot', 'camera_link', width=size, height=size, hfov=80.0, near=0.05,
                      far=40.0)


def median_ms(fn, frames, budget_s=3.0):
    """Median wall time (ms) of fn() over up to ``frames`` calls (fewer if slow)."""
    fn()   # warm-up
    times, start = [], time.perf_counter()
    while len(times) < frames and (len(times) < 5 or time.perf_counter() - start < budget_s):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return 1000.0 * statistics.median(times)


class Quiet(object):
    """The engine's logger here: the world's plugins are not run, and say so."""

    def info(self, text):
        pass

    warn = error = info


class Scene(object):
    """The dog world with one renderer backend, started in this thread."""

    def __init__(self, kind):
        self.engine = make_engine(egl=kind == 'egl', log=Quiet())
        self.backend = self.engine.handle.make_renderer(kind)
        self.backend.start()
        self.engine.step()

    def frame(self, cam):
        """One BGR frame (a copy: the gl backend reuses its buffer)."""
        return np.array(self.backend.finish(self.backend.capture(cam)))

    def close(self):
        self.backend.close()
        self.engine.close()


def bench_render(sizes, frames=60):
    """ms per frame of each renderer and size: render (capture + finish, as the
    simulator does), JPEG encode, and their sum."""
    rows = []
    for kind in RENDERERS:
        scene = Scene(kind)
        for size in sizes:
            cam = camera(size)
            render = median_ms(lambda: scene.backend.finish(scene.backend.capture(cam)),
                               frames)
            image = scene.frame(cam)
            encode = median_ms(lambda: encode_jpeg(image, 80), frames)
            rows.append(dict(renderer=kind, size=size, render_ms=render, encode_ms=encode,
                             frame_ms=render + encode))
        scene.close()
    return rows


def bench_vision(size, frames=200):
    """ms per real frame of the default scene: JPEG decode and ball detection,
    at full size (``ms``: the original's pipeline) and as the state machine
    runs them (``node_ms``: decoded at 1/vision_scale, detected there)."""
    scene = Scene('gl')
    cam, jpegs = camera(size), []
    for _ in range(20):      # the ball at a few places in view
        scene.engine.models['ball'].move_kinematic(0.0, -0.05, 0.0)
        jpegs.append(encode_jpeg(scene.frame(cam), 80))
    scene.close()
    detector, scale = BallDetector(), vision_scale(size)
    decoded = [decode_jpeg(j) for j in jpegs]
    reduced = [decode_jpeg(j, scale) for j in jpegs]
    i, found = iter(range(10 ** 9)), []

    def pick(items):
        return items[next(i) % len(items)]
    out = dict(scale=scale,
               decode_ms=median_ms(lambda: decode_jpeg(pick(jpegs)), frames),
               detect_ms=median_ms(lambda: detector.detect(pick(decoded)), frames),
               decode_reduced_ms=median_ms(lambda: decode_jpeg(pick(jpegs), scale), frames),
               detect_reduced_ms=median_ms(
                   lambda: found.append(detector.detect(pick(reduced), scale) is not None),
                   frames))
    out['ms'] = out['decode_ms'] + out['detect_ms']
    out['node_ms'] = out['decode_reduced_ms'] + out['detect_reduced_ms']
    out['frames_with_ball'] = sum(found) / float(len(found))
    return out


def side_by_side(path, size=400):
    """The same view drawn by gl, egl and tiny, labelled, in one PNG."""
    panels = []
    for kind in RENDERERS:
        scene = Scene(kind)
        image = scene.frame(camera(size))
        scene.close()
        cv2.putText(image, kind, (12, 40), cv2.FONT_HERSHEY_SIMPLEX, 1.2, (255, 255, 255), 5)
        cv2.putText(image, kind, (12, 40), cv2.FONT_HERSHEY_SIMPLEX, 1.2, (20, 20, 20), 2)
        panels.append(image)
    cv2.imwrite(path, np.hstack(panels))
    return path

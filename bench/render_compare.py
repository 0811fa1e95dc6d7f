#!/usr/bin/env python3
"""Compare the package's GL renderer with pybullet's EGL plugin and TinyRenderer.

Renders the default dog scene (arena with the grid floor, the seated human,
the robot, the ball ahead of it) from the robot's camera_link with each
renderer at the same pose, writes one labelled side-by-side PNG, and prints the
median ms per frame of each renderer at several image sizes.

    /usr/bin/python3 bench/render_compare.py /tmp/compare.png [--sizes 200 320 800 1280]

No ROS needed. pybullet's EGL plugin takes over every getCameraImage of the
client it is loaded in (TinyRenderer included) and only draws bodies loaded
after it: egl therefore gets its own client, plugin loaded first; gl and tiny
share a plain one.
"""
import argparse
import math
import os
import pkgutil
import statistics
import sys
import tempfile
import time

import cv2
import numpy as np
import pybullet as p

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, 'src'))
from exp_assignment2.sim.render_gl import BulletSceneReader, GLRenderer, SceneModel  # noqa: E402

HFOV, NEAR, FAR = 80.0, 0.05, 40.0


def grid_texture(size_m=20.0, px_per_m=32):
    """The simulator's floor texture: 200 grey, 90 grey lines 1/16 m wide every 1 m."""
    n = int(size_m * px_per_m)
    img = np.full((n, n, 3), 200, np.uint8)
    for i in range(0, n, px_per_m):
        img[i:i + 2, :] = 90
        img[:, i:i + 2] = 90
    path = os.path.join(tempfile.gettempdir(), 'render_compare_grid_%d.png' % n)
    cv2.imwrite(path, img)
    return path


def build_scene(client):
    """Load the default scene; returns (models, robot id, camera link index)."""
    q = p.getQuaternionFromEuler
    urdf = lambda name: os.path.join(ROOT, 'urdf', name)  # noqa: E731
    arena = p.loadURDF(urdf('arena.urdf'), useFixedBase=True, physicsClientId=client)
    human = p.loadURDF(urdf('human.urdf'), [-7, 7, 0], q([0, 0, -0.785]), useFixedBase=True,
                       physicsClientId=client)
    robot = p.loadURDF(urdf('robot.urdf'), [-5, 7, 0.1], q([0, 0, math.pi]),
                       physicsClientId=client)
    ball = p.loadURDF(urdf('ball.urdf'), [-7.5, 6.3, 0.5], useFixedBase=True,
                      physicsClientId=client)
    tex = p.loadTexture(grid_texture(), physicsClientId=client)
    p.changeVisualShape(arena, -1, textureUniqueId=tex, physicsClientId=client)
    links = {p.getJointInfo(robot, j, physicsClientId=client)[12].decode(): j
             for j in range(p.getNumJoints(robot, physicsClientId=client))}
    models = [SceneModel(arena, urdf('arena.urdf'), True, 'arena'),
              SceneModel(human, urdf('human.urdf'), False, 'human'),
              SceneModel(robot, urdf('robot.urdf'), False, 'robot'),
              SceneModel(ball, urdf('ball.urdf'), False, 'ball')]
    return models, robot, links['camera_link']


def median_ms(fn, frames, budget_s=2.0):
    """Median wall time (ms) of fn() over up to ``frames`` calls (fewer if slow)."""
    fn()   # warm-up
    times, start = [], time.perf_counter()
    while len(times) < frames and (len(times) < 5 or time.perf_counter() - start < budget_s):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return 1000.0 * statistics.median(times), len(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('out', help='side-by-side PNG to write')
    ap.add_argument('--sizes', type=int, nargs='+', default=[200, 320, 800, 1280])
    ap.add_argument('--image-size', type=int, default=320, help='panel size in the PNG')
    ap.add_argument('--frames', type=int, default=100, help='frames per timing (at most)')
    args = ap.parse_args()

    client, egl_client = p.connect(p.DIRECT), p.connect(p.DIRECT)
    loader = pkgutil.get_loader('eglRenderer')
    plugin = (p.loadPlugin(loader.get_filename(), '_eglRendererPlugin',
                           physicsClientId=egl_client) if loader is not None else -1)
    models, robot, cam_link = build_scene(client)
    build_scene(egl_client)
    reader = BulletSceneReader(models, client)
    pos, quat = p.getLinkState(robot, cam_link, computeForwardKinematics=1,
                               physicsClientId=client)[4:6]
    pos, rot = np.array(pos), np.array(p.getMatrixFromQuaternion(quat)).reshape(3, 3)

    def bullet(kind, w, h):
        view = p.computeViewMatrix(pos.tolist(), (pos + rot[:, 0]).tolist(), rot[:, 2].tolist())
        vfov = math.degrees(2 * math.atan(math.tan(math.radians(HFOV) / 2) * h / w))
        proj = p.computeProjectionMatrixFOV(vfov, w / float(h), NEAR, FAR)
        renderer = p.ER_TINY_RENDERER if kind == 'tiny' else p.ER_BULLET_HARDWARE_OPENGL
        cid = client if kind == 'tiny' else egl_client
        return lambda: p.getCameraImage(w, h, view, proj, renderer=renderer,
                                        flags=p.ER_NO_SEGMENTATION_MASK, physicsClientId=cid)

    def bullet_bgr(kind, w, h):
        rgba = np.asarray(bullet(kind, w, h)()[2], np.uint8).reshape(h, w, 4)
        return cv2.cvtColor(rgba, cv2.COLOR_RGBA2BGR)

    kinds = ['gl'] + (['egl'] if plugin >= 0 else []) + ['tiny']
    if plugin < 0:
        print("pybullet's EGL plugin did not load: egl skipped")
    # the picture
    s = args.image_size
    panels = []
    for kind in kinds:
        if kind == 'gl':
            with GLRenderer(reader.description, s, s) as gl:
                img = gl.render(reader.read_poses(), (pos, rot), HFOV, NEAR, FAR).copy()
        else:
            img = bullet_bgr(kind, s, s)
        cv2.putText(img, kind, (8, 28), cv2.FONT_HERSHEY_SIMPLEX, 0.9, (0, 0, 255), 2)
        panels.append(img)
    cv2.imwrite(args.out, np.hstack(panels))
    print('wrote %s (%s, %dx%d each)' % (args.out, ' | '.join(kinds), s, s))

    # the timings
    print('median ms per frame (frames timed); gl = render() incl. BGR read-back, '
          'egl/tiny = getCameraImage() alone')
    poses = reader.read_poses()
    print('gl read_poses (simulator thread): %.3f ms' % median_ms(reader.read_poses, 200)[0])
    print('%6s ' % 'size' + ' '.join('%16s' % k for k in kinds))
    for size in args.sizes:
        row = []
        for kind in kinds:
            if kind == 'gl':
                with GLRenderer(reader.description, size, size) as gl:
                    ms, n = median_ms(lambda: gl.render(poses, (pos, rot), HFOV, NEAR, FAR),
                                      args.frames)
            else:
                ms, n = median_ms(bullet(kind, size, size), args.frames)
            row.append('%9.2f (%4d)' % (ms, n))
        print('%6d ' % size + ' '.join('%16s' % r for r in row))
    if plugin >= 0:
        p.unloadPlugin(plugin, physicsClientId=egl_client)
    p.disconnect(egl_client)
    p.disconnect(client)


if __name__ == '__main__':
    main()

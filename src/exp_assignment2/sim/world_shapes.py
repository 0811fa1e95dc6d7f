"""The world's scenery as shapes, for rviz: every static model's visuals at
their poses, and a 1 m grid on grid floors (no ROS). The same models that
build the physics and the camera's picture build this, so what rviz shows
is what the robot meets.

A :class:`Shape` is one visual in the world frame; :func:`grid_lines` the
floor grid's segments. :mod:`exp_assignment2.ros.world_markers` turns them
into a ``visualization_msgs/MarkerArray``.
"""
import math
from collections import namedtuple

import numpy as np

from exp_assignment2.sim.rotations import pose_matrix

Shape = namedtuple('Shape', 'model link kind params pose rgba')
Shape.__doc__ = """One visual: ``kind`` (box, cylinder, sphere, capsule, mesh), its
``params`` (as :class:`~exp_assignment2.sim.urdf_elements.Visual`), its 4x4 world ``pose``."""


def scenery(models):
    """The static models among ``models`` (what is shown as the world)."""
    return [m for m in models if m.static]


def shapes(models):
    """Every visual of every static model, posed in the world."""
    out = []
    for model in scenery(models):
        for link, visuals in model.urdf.visuals.items():
            if not visuals or link not in model.body.links:
                continue
            frame = pose_matrix(*model.link_pose(link))
            for visual in visuals:
                out.append(Shape(model.name, link, visual.kind, visual.params,
                                 frame.dot(visual.origin), visual.rgba))
    return out


def grid_lines(models, step=1.0, lift=0.005):
    """Segments ((x0, y0, z), (x1, y1, z)) of a ``step`` grid on the top face
    of every grid model's base link boxes: lines at the whole multiples of
    ``step`` within the box, from the first such line to the last."""
    segments = []
    for model in models:
        if not model.grid:
            continue
        frame = pose_matrix(*model.pose())
        for visual in model.urdf.links[model.base_frame].visuals:
            if visual.kind != 'box':
                continue
            centre = frame.dot(visual.origin)[:3, 3]
            half = np.asarray(visual.params['size']) / 2.0
            xs = _steps(centre[0] - half[0], centre[0] + half[0], step)
            ys = _steps(centre[1] - half[1], centre[1] + half[1], step)
            if not xs or not ys:
                continue
            z = centre[2] + half[2] + lift
            segments += [((x, ys[0], z), (x, ys[-1], z)) for x in xs]
            segments += [((xs[0], y, z), (xs[-1], y, z)) for y in ys]
    return segments


def _steps(low, high, step):
    first = math.ceil(low / step - 1e-9)
    last = math.floor(high / step + 1e-9)
    return [k * step for k in range(first, last + 1)]


def signature(models):
    """Changes when the scenery changes (a model spawned, deleted or moved)."""
    return tuple((m.name, tuple(round(v, 3) for v in m.pose()[0]),
                  tuple(round(v, 3) for v in m.pose()[1])) for m in scenery(models))

"""What the GL renderer draws, split along pybullet's threading rule.

* :class:`SceneReader` lives in the simulator's thread (pybullet is not
  thread-safe). Built from the world's models (each with its parsed URDF,
  :class:`~exp_assignment2.sim.urdf.UrdfModel`, the one the physics loaded),
  it turns their visuals into a :class:`SceneDescription` (plain numpy
  data); per frame :meth:`~SceneReader.read_poses` returns every link's
  world frame as one new ``(n_slots, 4, 4)`` float32 array (one batched
  pybullet query per body), which may be handed to another thread.
* :class:`~.renderer.GLRenderer` owns an OpenGL context bound to the thread
  that constructs it (e.g. the camera's worker) and draws a description.

A model to draw is anything with ``name``, ``id`` (pybullet body id), ``urdf``
and ``grid`` (its base link gets the 1 m floor grid: True in every camera's
view, :data:`~exp_assignment2.sim.model.GUI_GRID` in Gazebo's user camera's
only): a :class:`~exp_assignment2.sim.model.Model`, or :class:`Drawable` in tests.
"""
import os
from collections import namedtuple

import numpy as np

from ..rotations import pose_matrix, quaternion_matrices
from ..urdf import parse
from .meshes import indexed, visual_vertices
from .renderer import GLRenderer, view_projection

__all__ = ['Drawable', 'GLRenderer', 'SceneDescription', 'SceneReader', 'view_projection']

Drawable = namedtuple('Drawable', 'name id urdf grid')
NO_GRID, GRID, GUI_GRID_ONLY = 0, 1, 2      # a draw's grid: none, always, the user camera's


def drawable(body_id, path, grid=False, name=None):
    """A :class:`Drawable` for a body loaded from the URDF file ``path``."""
    with open(path) as f:
        urdf = parse(f.read(), os.path.dirname(os.path.abspath(path)))
    return Drawable(name or urdf.name, body_id, urdf, grid)


class SceneDescription(object):
    """What to draw, as plain numpy data (no pybullet, no GL; read-only once built).

    ``vertices``: (n, 9) float32 rows (:data:`.meshes.VERTEX_FORMAT`) in
    their link's frame; ``indices``: uint32 triangle corners; ``draws``: (slot,
    first index, index count, cull back faces, grid) per group, grid floors
    last (grid: :data:`NO_GRID`, :data:`GRID` or :data:`GUI_GRID_ONLY`);
    ``slots``: (model name, link name) per pose slot; ``model_names``,
    ``body_ids`` and ``model_slots`` (slot range start, stop) per model.
    """

    def __init__(self, vertices, indices, draws, slots, model_names, body_ids, model_slots):
        self.vertices, self.indices, self.draws = vertices, indices, draws
        self.slots, self.model_names = slots, model_names
        self.body_ids, self.model_slots = body_ids, model_slots
        self._index = {s: i for i, s in enumerate(slots)}

    @property
    def n_slots(self):
        """Number of pose slots (every link of every model, bases included)."""
        return len(self.slots)

    def slot(self, model, link):
        """Pose slot of link ``link`` of model ``model`` (KeyError if unknown)."""
        return self._index[(model, link)]

    def link_pose(self, poses, model, link):
        """4x4 world frame of a link in a :meth:`SceneReader.read_poses`
        snapshot, e.g. the camera's: ``link_pose(poses, 'robot', 'camera_link')``."""
        return poses[self.slot(model, link)].astype(float)

    def hidden_slots(self, hidden):
        """Set of the slots of the models in ``hidden`` (names or body ids)."""
        out = set()
        for h in hidden:
            if h in self.model_names:
                k = self.model_names.index(h)
            elif h in self.body_ids:
                k = self.body_ids.index(h)
            else:
                continue       # deleted meanwhile
            out.update(range(*self.model_slots[k]))
        return out


def empty_description():
    """A scene with nothing in it."""
    return SceneDescription(np.zeros((0, 9), np.float32), np.zeros(0, np.uint32), [], [], [],
                            [], [])


class SceneReader(object):
    """The simulator-thread half: URDF visuals and batched pose reads from pybullet.

    :param models: models to draw (see the module docstring)
    :param client: pybullet physics client id
    Construct it and call :meth:`read_poses` in the thread that owns the client.
    """

    def __init__(self, models, client=0):
        import pybullet as p   # here, so that the GL half imports without pybullet
        self._p, self.client = p, client
        self._bodies = []      # (body id, link indices)
        groups, slots, names, ids, ranges, inv_inertial = {}, [], [], [], [], []
        for model in models:
            body_id, urdf = model.id, model.urdf
            first, n_links = len(slots), p.getNumJoints(body_id, physicsClientId=client)
            index = {urdf.root: -1}
            for j in range(n_links):
                index[p.getJointInfo(body_id, j, physicsClientId=client)[12].decode()] = j
            by_index = {v: k for k, v in index.items()}
            slots += [(model.name, by_index[j]) for j in range(-1, n_links)]
            for link, visuals in urdf.visuals.items():
                # A link pybullet merged away (URDF_MERGE_FIXED_LINKS) rides on
                # its nearest kept ancestor through the fixed joints between.
                frame, at = np.eye(4), link
                while at not in index and urdf.parent_joint(at) is not None:
                    joint = urdf.parent_joint(at)
                    frame, at = joint.origin.dot(frame), joint.parent
                if at not in index:
                    raise ValueError('model %s: link %s is not in pybullet body %d'
                                     % (model.name, link, body_id))
                # The grid goes where the simulator put pybullet's grid
                # texture: on the base link of a grid model.
                is_grid = NO_GRID if not model.grid or index[at] != -1 else \
                    GRID if model.grid is True else GUI_GRID_ONLY
                for v in visuals:
                    rows = visual_vertices(v, frame)
                    if rows is not None:
                        # primitives are closed and wound outwards: cull their
                        # back faces (halves llvmpipe's work); meshes may not be
                        key = (is_grid, first + index[at] + 1, v.kind != 'mesh')
                        groups.setdefault(key, []).append(rows)
            # getBasePositionAndOrientation gives the base's inertial frame; the
            # URDF base frame is that times the inverse local inertial frame.
            info = p.getDynamicsInfo(body_id, -1, physicsClientId=client)
            inv_inertial.append(np.linalg.inv(pose_matrix(info[3], info[4])))
            names.append(model.name)
            ids.append(body_id)
            ranges.append((first, len(slots)))
            self._bodies.append((body_id, list(range(n_links))))
        # Grid floors last: early depth test then skips their costly fragments
        # wherever something stands in front of them.
        vertices, indices, draws, n_vertices, n_indices = [], [], [], 0, 0
        for is_grid, slot, cull in sorted(groups):
            rows, idx = indexed(np.concatenate(groups[(is_grid, slot, cull)]))
            vertices.append(rows)
            indices.append(idx + n_vertices)
            draws.append((slot, n_indices, len(idx), cull, is_grid))
            n_vertices, n_indices = n_vertices + len(rows), n_indices + len(idx)
        self.description = SceneDescription(
            np.concatenate(vertices) if vertices else np.zeros((0, 9), np.float32),
            np.concatenate(indices) if indices else np.zeros(0, np.uint32),
            draws, slots, names, ids, ranges)
        self._inv_inertial = np.array(inv_inertial).reshape(-1, 4, 4)
        self._base_slots = np.array([r[0] for r in ranges], int)

    def read_poses(self):
        """World frames of every slot: a new (n_slots, 4, 4) float32 array (safe
        to hand to another thread); one base + one getLinkStates query per body."""
        p, c = self._p, self.client
        pos, quat = [], []
        for body_id, links in self._bodies:
            base = p.getBasePositionAndOrientation(body_id, physicsClientId=c)
            pos.append(base[0])
            quat.append(base[1])
            if links:
                for s in p.getLinkStates(body_id, links, computeForwardKinematics=1,
                                         physicsClientId=c):
                    pos.append(s[4])   # the URDF link frame, not the inertial one
                    quat.append(s[5])
        m = np.zeros((len(pos), 4, 4))
        if pos:
            m[:, :3, :3] = quaternion_matrices(quat)
            m[:, :3, 3] = pos
            m[:, 3, 3] = 1.0
            m[self._base_slots] = np.matmul(m[self._base_slots], self._inv_inertial)
        return m.astype(np.float32)

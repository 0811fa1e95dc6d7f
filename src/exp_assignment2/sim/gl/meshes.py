"""URDF visuals as triangle arrays for the GL renderer (:mod:`.renderer`).

Plain numpy (no pybullet, no GL): tessellation of the URDF primitives (box,
cylinder, sphere, capsule), OBJ and STL mesh loading, and
:func:`visual_triangles` / :func:`visual_vertices`, which turn one parsed
:class:`~exp_assignment2.sim.urdf_elements.Visual` into triangles (positions and normals in the
link frame) or vertex rows; :func:`indexed` shares their repeated vertices.
"""
import logging
import math
import os

import numpy as np

log = logging.getLogger(__name__)

VERTEX_FORMAT = '3f 3f 3f'   # a vertex row: position, normal (link frame), rgb
CYLINDER_SEGMENTS = 48
# Sphere (segments, rings) by radius: software GL pays per visible triangle,
# and a small sphere never covers enough pixels to show 32 facets. The largest
# (2976 triangles) keeps the outline within 0.2 % of the radius.
SPHERE_DETAIL = ((0.25, (48, 32)), (0.08, (32, 20)), (0.0, (20, 12)))


# Primitive shapes: (positions, normals) float arrays of shape (3 * n_triangles, 3),
# counter-clockwise seen from outside.
def box_triangles(size):
    """A box of ``size`` (x, y, z) centred on the origin, flat normals."""
    h = np.asarray(size, float) / 2.0
    pos, nrm = [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = np.zeros(3)
            n[axis] = sign
            u, v = np.zeros(3), np.zeros(3)
            u[(axis + 1) % 3], v[(axis + 2) % 3] = 1.0, 1.0
            if sign < 0:
                u, v = v, u   # keep the winding counter-clockwise from outside
            c = n * h
            corners = [c + (su * u + sv * v) * h
                       for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            pos += [corners[i] for i in (0, 1, 2, 0, 2, 3)]
            nrm += [n] * 6
    return np.array(pos), np.array(nrm)


def _ring(radius, segments):
    a = np.linspace(0.0, 2.0 * math.pi, segments + 1)
    return np.stack([np.cos(a), np.sin(a), np.zeros_like(a)], 1) * [radius, radius, 0]


def cylinder_triangles(radius, length, segments=CYLINDER_SEGMENTS):
    """A cylinder along z centred on the origin: smooth side, flat caps."""
    ring = _ring(radius, segments)
    top, bot = ring + [0, 0, length / 2.0], ring - [0, 0, length / 2.0]
    side_n = ring / radius
    pos, nrm = [], []
    for i in range(segments):
        j = i + 1
        pos += [bot[i], bot[j], top[j], bot[i], top[j], top[i]]
        nrm += [side_n[i], side_n[j], side_n[j], side_n[i], side_n[j], side_n[i]]
        pos += [[0, 0, length / 2.0], top[i], top[j]]
        nrm += [[0, 0, 1]] * 3
        pos += [[0, 0, -length / 2.0], bot[j], bot[i]]
        nrm += [[0, 0, -1]] * 3
    return np.array(pos, float), np.array(nrm, float)


def sphere_triangles(radius, segments=None, rings=None):
    """A UV sphere centred on the origin with smooth (radial) normals;
    detail from SPHERE_DETAIL unless given."""
    if segments is None:
        segments, rings = next(d for r, d in SPHERE_DETAIL if radius >= r)
    th = np.linspace(0.0, math.pi, rings + 1)[:, None]          # from +z down
    ph = np.linspace(0.0, 2.0 * math.pi, segments + 1)[None, :]
    n = np.stack(np.broadcast_arrays(np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph),
                                     np.cos(th)), -1)            # (rings+1, segs+1, 3)
    a, b = n[:-1, :-1], n[1:, :-1]
    c, d = n[1:, 1:], n[:-1, 1:]
    tris = np.stack([a, b, c, a, c, d], 2).reshape(rings, segments, 2, 3, 3)
    # at the poles one triangle of each quad has zero area: drop it
    keep = np.ones((rings, segments, 2), bool)
    keep[0, :, 1] = False
    keep[-1, :, 0] = False
    nrm = tris[keep].reshape(-1, 3)
    return nrm * radius, nrm


def capsule_triangles(radius, length):
    """pybullet's <capsule>: a cylinder along z capped by two half spheres."""
    p, n = sphere_triangles(radius)
    p = p + np.where(p[:, 2:3] >= 0, 1.0, -1.0) * [0, 0, length / 2.0]
    cp, cn = cylinder_triangles(radius, length)
    side = np.abs(cn[:, 2]) < 0.5
    return np.concatenate([p, cp[side]]), np.concatenate([n, cn[side]])


def _face_normals(pos):
    tri = pos.reshape(-1, 3, 3)
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-12)
    return np.repeat(n, 3, axis=0)


def load_obj(path):
    """Triangles of a Wavefront OBJ (v / vn / f; polygons fanned; materials ignored)."""
    verts, norms, pos, nrm = [], [], [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == 'v':
                verts.append([float(x) for x in parts[1:4]])
            elif parts[0] == 'vn':
                norms.append([float(x) for x in parts[1:4]])
            elif parts[0] == 'f':
                corners = []
                for c in parts[1:]:
                    idx = c.split('/')
                    vi = int(idx[0])
                    ni = int(idx[2]) if len(idx) > 2 and idx[2] else 0
                    # OBJ indices are 1-based; negative ones count from the end
                    corners.append((vi - 1 if vi > 0 else len(verts) + vi,
                                    (ni - 1 if ni > 0 else len(norms) + ni) if ni else None))
                for k in range(1, len(corners) - 1):
                    for vi, ni in (corners[0], corners[k], corners[k + 1]):
                        pos.append(verts[vi])
                        nrm.append(norms[ni] if ni is not None else None)
    pos = np.array(pos, float).reshape(-1, 3)
    flat = _face_normals(pos)
    # vertices without a usable vn take the face normal
    nrm = np.array([n if n is not None else f for n, f in zip(nrm, flat)], float).reshape(-1, 3)
    return pos, nrm


def load_stl(path):
    """Triangles of a binary or ASCII STL (normals from the winding, not the file)."""
    with open(path, 'rb') as f:
        data = f.read()
    if len(data) >= 84:
        n = int(np.frombuffer(data, '<u4', 1, 80)[0])
        if len(data) == 84 + 50 * n:   # binary: the size formula decides, not "solid"
            rec = np.frombuffer(data, np.dtype([('n', '<f4', 3), ('v', '<f4', (3, 3)),
                                                ('a', '<u2')]), n, 84)
            pos = rec['v'].reshape(-1, 3).astype(float)
            return pos, _face_normals(pos)
    words = data.decode('ascii', 'replace').split()
    pos = [[float(x) for x in words[i + 1:i + 4]] for i, w in enumerate(words) if w == 'vertex']
    pos = np.array(pos, float).reshape(-1, 3)
    return pos, _face_normals(pos)


MESH_LOADERS = {'.obj': load_obj, '.stl': load_stl}


def visual_triangles(visual):
    """(positions, normals) of a :class:`~exp_assignment2.sim.urdf_elements.Visual`
    in its link frame, or None (with a warning) for a mesh that cannot be loaded."""
    kind, prm = visual.kind, visual.params
    if kind == 'box':
        pos, nrm = box_triangles(prm['size'])
    elif kind == 'cylinder':
        pos, nrm = cylinder_triangles(prm['radius'], prm['length'])
    elif kind == 'capsule':
        pos, nrm = capsule_triangles(prm['radius'], prm['length'])
    elif kind == 'sphere':
        pos, nrm = sphere_triangles(prm['radius'])
    else:
        fn = prm['filename']
        loader = MESH_LOADERS.get(os.path.splitext(fn)[1].lower())
        if loader is None or not os.path.exists(fn):
            log.warning('mesh %s: %s, not drawn', fn,
                        'no such file' if loader else 'only OBJ and STL are supported')
            return None
        pos, nrm = loader(fn)
        scale = np.asarray(prm['scale'], float)
        pos = pos * scale
        # normals transform by the inverse scale (non-uniform scaling)
        nrm = nrm / np.where(scale == 0, 1.0, scale)
        nrm /= np.maximum(np.linalg.norm(nrm, axis=1, keepdims=True), 1e-12)
    r, t = visual.origin[:3, :3], visual.origin[:3, 3]
    return pos.dot(r.T) + t, nrm.dot(r.T)


def visual_vertices(visual, frame=None):
    """Vertex rows [x y z nx ny nz r g b] (float32, VERTEX_FORMAT; one per corner)
    of a :class:`~exp_assignment2.sim.urdf_elements.Visual`, moved by the 4x4
    ``frame`` if given; or None."""
    tri = visual_triangles(visual)
    if tri is None:
        return None
    pos, nrm = tri
    if frame is not None:
        pos, nrm = pos.dot(frame[:3, :3].T) + frame[:3, 3], nrm.dot(frame[:3, :3].T)
    rows = np.empty((len(pos), 9), np.float32)
    rows[:, 0:3], rows[:, 3:6], rows[:, 6:9] = pos, nrm, visual.rgba[:3]
    return rows


def indexed(rows):
    """(unique rows, uint32 indices) of per-corner vertex rows: GL then shades
    each shared vertex once instead of once per triangle corner."""
    unique, inverse = np.unique(rows, axis=0, return_inverse=True)
    return unique, inverse.astype(np.uint32).ravel()

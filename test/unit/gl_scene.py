"""The scene the renderer tests draw: the dog world in a pybullet DIRECT
client, pybullet's TinyRenderer for comparison, mesh fixtures (not a test by
itself)."""
import math
import os
import struct

import numpy as np
import pytest

p = pytest.importorskip('pybullet')
cv2 = pytest.importorskip('cv2')

from exp_assignment2.sim import urdf as urdf_shapes  # noqa: E402
from exp_assignment2.sim.gl import meshes as gl_meshes  # noqa: E402
from exp_assignment2.sim.gl.scene import GLRenderer, SceneReader, drawable  # noqa: E402

URDF = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), 'urdf')
W = H = 320
HFOV, NEAR, FAR = 80.0, 0.05, 40.0
BALL_Z = 0.5


def parse_file(name):
    """The package's URDF ``name``, parsed."""
    with open(os.path.join(URDF, name)) as f:
        return urdf_shapes.parse(f.read(), URDF)


def focal(width, hfov=HFOV):
    return width / (2.0 * math.tan(math.radians(hfov) / 2.0))


def tiny_image(client, cam, width=W, height=H, pixel_centres=True):
    """pybullet TinyRenderer image (BGR) from camera (position, rotation).

    As pybullet sets it up, TinyRenderer's image lies half a pixel right of and
    above the pinhole's (GL's): consistent with it testing coverage at pixel
    corners instead of centres. ``pixel_centres`` moves its projection half a
    pixel left and down; it then draws a box's pixels exactly as GL does
    (test_tiny_renderer_at_pixel_centres_draws_boxes_as_gl)."""
    pos, rot = cam
    view = p.computeViewMatrix(pos.tolist(), (pos + rot[:, 0]).tolist(), rot[:, 2].tolist())
    aspect = float(width) / height
    vfov = math.degrees(2.0 * math.atan(math.tan(math.radians(HFOV) / 2.0) / aspect))
    proj = list(p.computeProjectionMatrixFOV(vfov, aspect, NEAR, FAR))
    if pixel_centres:
        # column-major: clip x, y gain (1/width, 1/height) * z_eye, and clip
        # w = -z_eye, so NDC x, y lose 1/width, 1/height: half a pixel each
        proj[8] += 1.0 / width
        proj[9] += 1.0 / height
    rgba = p.getCameraImage(width, height, view, proj, renderer=p.ER_TINY_RENDERER,
                            flags=p.ER_NO_SEGMENTATION_MASK, physicsClientId=client)[2]
    return cv2.cvtColor(np.asarray(rgba, np.uint8).reshape(height, width, 4),
                        cv2.COLOR_RGBA2BGR)


class Scene(object):
    """The dog scene in a pybullet DIRECT client, with helpers to pose it."""

    def __init__(self):
        c = self.client = p.connect(p.DIRECT)
        q = p.getQuaternionFromEuler
        self.urdf = {n: os.path.join(URDF, n + '.urdf')
                     for n in ('arena', 'human', 'robot', 'ball')}
        self.arena = p.loadURDF(self.urdf['arena'], useFixedBase=True, physicsClientId=c)
        self.human = p.loadURDF(self.urdf['human'], [-7, 7, 0], q([0, 0, -0.785]),
                                useFixedBase=True, physicsClientId=c)
        self.robot = p.loadURDF(self.urdf['robot'], [-5, 7, 0.1], q([0, 0, math.pi]),
                                physicsClientId=c)
        self.ball = p.loadURDF(self.urdf['ball'], [-7, 6, BALL_Z], useFixedBase=True,
                               physicsClientId=c)
        info = [p.getJointInfo(self.robot, j, physicsClientId=c)
                for j in range(p.getNumJoints(self.robot, physicsClientId=c))]
        self.camera_link = [i[12].decode() for i in info].index('camera_link')
        self.head_joint = [i[1].decode() for i in info].index('head_joint')
        self.reader = SceneReader(
            [drawable(self.arena, self.urdf['arena'], True, 'arena'),
             drawable(self.human, self.urdf['human'], False, 'human'),
             drawable(self.robot, self.urdf['robot'], False, 'robot'),
             drawable(self.ball, self.urdf['ball'], False, 'ball')], c)

    def pose_robot(self, yaw=math.pi, head=0.0):
        """Put the robot at (-5, 7) facing ``yaw`` with the head at ``head``;
        return the camera's (position, rotation) from pybullet."""
        c = self.client
        p.resetBasePositionAndOrientation(self.robot, [-5, 7, 0.1],
                                          p.getQuaternionFromEuler([0, 0, yaw]), physicsClientId=c)
        p.resetJointState(self.robot, self.head_joint, head, physicsClientId=c)
        pos, quat = p.getLinkState(self.robot, self.camera_link, computeForwardKinematics=1,
                                   physicsClientId=c)[4:6]
        return np.array(pos), np.array(p.getMatrixFromQuaternion(quat)).reshape(3, 3)

    def put_ball(self, xyz):
        p.resetBasePositionAndOrientation(self.ball, list(xyz), [0, 0, 0, 1],
                                          physicsClientId=self.client)

    def ball_ahead(self, cam, dist, lateral=0.0):
        pos, rot = cam
        b = pos + dist * rot[:, 0] + lateral * rot[:, 1]
        b[2] = BALL_Z
        self.put_ball(b)

    def tiny(self, cam, width=W, height=H, pixel_centres=True):
        """:func:`tiny_image` of this scene."""
        return tiny_image(self.client, cam, width, height, pixel_centres)


@pytest.fixture(scope='module')
def scene():
    s = Scene()
    yield s
    p.disconnect(s.client)


def make_renderer(description, width=W, height=H, **kw):
    """A GLRenderer, or skip the test with the renderer's one-line reason."""
    try:
        return GLRenderer(description, width, height, **kw)
    except RuntimeError as exc:
        pytest.skip(str(exc))


@pytest.fixture(scope='module')
def gl(scene):
    r = make_renderer(scene.reader.description)
    yield r
    r.close()


def render(gl, scene, cam, **kw):
    return gl.render(scene.reader.read_poses(), cam, HFOV, NEAR, FAR, **kw).copy()


def cube_obj(path):
    """A unit cube as OBJ quads with normals (faces counter-clockwise from outside)."""
    v = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
    faces = [((0, 1, 3, 2), (-1, 0, 0)), ((4, 6, 7, 5), (1, 0, 0)), ((0, 4, 5, 1), (0, -1, 0)),
             ((2, 3, 7, 6), (0, 1, 0)), ((0, 2, 6, 4), (0, 0, -1)), ((1, 5, 7, 3), (0, 0, 1))]
    lines = ['v %g %g %g' % c for c in v] + ['vn %g %g %g' % n for _, n in faces]
    lines += ['f ' + ' '.join('%d//%d' % (i + 1, k + 1) for i in f)
              for k, (f, _) in enumerate(faces)]
    path.write_text('\n'.join(lines) + '\n')
    return gl_meshes.load_obj(str(path))


def cube_stl(path, triangles):
    """Binary STL of the given (n*3, 3) triangle corners."""
    tri = triangles.reshape(-1, 3, 3)
    data = b'\0' * 80 + struct.pack('<I', len(tri))
    for t in tri:
        data += struct.pack('<12fH', 0, 0, 0, *t.ravel(), 0)
    path.write_bytes(data)


def mesh_world(tmp_path):
    """A body whose base is an OBJ cube (red) with an offset, rotated inertial
    frame, and a fixed child link 1 m to its left that is an STL cube (blue)."""
    pos, _ = cube_obj(tmp_path / 'cube.obj')
    cube_stl(tmp_path / 'cube.stl', pos)
    (tmp_path / 'meshes.urdf').write_text('''<?xml version="1.0"?>
<robot name="meshes">
  <material name="red"><color rgba="0.9 0.1 0.1 1"/></material>
  <link name="base">
    <inertial><origin xyz="0.3 0.1 0" rpy="0 0 0.5"/><mass value="1"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
    <visual><geometry><mesh filename="cube.obj" scale="0.4 0.4 0.4"/></geometry>
      <material name="red"/></visual>
  </link>
  <link name="side">
    <inertial><mass value="1"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
    <visual><geometry><mesh filename="cube.stl" scale="0.4 0.4 0.4"/></geometry>
      <material name="blue"><color rgba="0.1 0.1 0.9 1"/></material></visual>
  </link>
  <joint name="fix" type="fixed"><parent link="base"/><child link="side"/>
    <origin xyz="0 1 0"/></joint>
</robot>
''')
    return one_body_world(str(tmp_path / 'meshes.urdf'), [0, 0, 1])


def one_body_world(urdf, position):
    """A DIRECT client with ``urdf`` loaded fixed at ``position``, and its reader."""
    c = p.connect(p.DIRECT)
    body = p.loadURDF(urdf, position, useFixedBase=True, physicsClientId=c)
    return c, SceneReader([drawable(body, urdf, False, 'm')], c)



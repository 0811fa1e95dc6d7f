"""The GL renderer's geometry without GL: the projection, link frames from
pybullet, URDF visuals and mesh loaders (no ROS, no catkin build)."""
import math
import os

import numpy as np
import pytest

from gl_scene import (FAR, HFOV, NEAR, cube_obj, cube_stl, focal, gl_meshes, p,  # noqa: F401
                      parse_file, scene)
from exp_assignment2.sim.gl.scene import view_projection
from exp_assignment2.sim.rotations import pose_matrix, rpy_matrix
from exp_assignment2.sim.urdf_elements import resolve_mesh_path


def test_projection_is_the_pinhole_and_pybullets():
    """view_projection puts points where f = w / (2 tan(hfov/2)), cx = w/2,
    cy = h/2 put them, and where pybullet's view + projection matrices do."""
    rng = np.random.default_rng(1)
    for width, height in ((320, 320), (400, 240)):
        pos = np.array([1.0, -2.0, 0.4])
        yaw, pitch = 0.7, 0.2
        rot = rpy_matrix(0.0, pitch, yaw)
        cam = np.eye(4)
        cam[:3, :3], cam[:3, 3] = rot, pos
        local = np.stack([rng.uniform(1, 10, 50), rng.uniform(-3, 3, 50),
                          rng.uniform(-2, 2, 50)], 1)   # camera frame: x ahead, y left, z up
        pts = pos + local.dot(rot.T)
        clip = view_projection(cam, width, height, HFOV, NEAR, FAR).dot(
            np.c_[pts, np.ones(len(pts))].T)
        u = (clip[0] / clip[3] + 1) / 2 * width
        v = (clip[1] / clip[3] + 1) / 2 * height     # flipped: row 0 at the top
        f = focal(width)
        np.testing.assert_allclose(u, width / 2.0 - f * local[:, 1] / local[:, 0], atol=1e-6)
        np.testing.assert_allclose(v, height / 2.0 - f * local[:, 2] / local[:, 0], atol=1e-6)
        aspect = float(width) / height
        vfov = math.degrees(2.0 * math.atan(math.tan(math.radians(HFOV) / 2.0) / aspect))
        vm = np.array(p.computeViewMatrix(pos.tolist(), (pos + rot[:, 0]).tolist(),
                                          rot[:, 2].tolist())).reshape(4, 4).T
        pm = np.array(p.computeProjectionMatrixFOV(vfov, aspect, NEAR, FAR)).reshape(4, 4).T
        bullet = pm.dot(vm).dot(np.c_[pts, np.ones(len(pts))].T)
        np.testing.assert_allclose(u, (bullet[0] / bullet[3] + 1) / 2 * width, atol=1e-3)
        np.testing.assert_allclose(v, (1 - bullet[1] / bullet[3]) / 2 * height, atol=1e-3)


def test_read_poses_are_pybullets_link_frames(scene):
    scene.pose_robot(math.pi, 0.4)
    poses = scene.reader.read_poses()
    d = scene.reader.description
    assert poses.dtype == np.float32 and poses.shape == (d.n_slots, 4, 4)
    for (model, link), pose in zip(d.slots, poses):
        body = {'arena': scene.arena, 'human': scene.human, 'robot': scene.robot,
                'ball': scene.ball}[model]
        n = p.getNumJoints(body, physicsClientId=scene.client)
        names = [p.getJointInfo(body, j, physicsClientId=scene.client)[12].decode()
                 for j in range(n)]
        if link in names:
            pos, quat = p.getLinkState(body, names.index(link), computeForwardKinematics=1,
                                       physicsClientId=scene.client)[4:6]
        else:   # the base: with an identity inertial frame, its pose
            pos, quat = p.getBasePositionAndOrientation(body, physicsClientId=scene.client)
        np.testing.assert_allclose(pose, pose_matrix(pos, quat), atol=1e-5)
    cam = scene.pose_robot(math.pi, 0.4)
    np.testing.assert_allclose(d.link_pose(poses, 'robot', 'camera_link')[:3, 3], cam[0],
                               atol=1e-5)
    scene.pose_robot()


def test_urdf_visuals_materials_and_origins():
    human = parse_file('human.urdf')
    assert [len(human.visuals[k]) for k in ('chair', 'body')] == [3, 4]   # all <visual>s
    assert human.visuals['body'][3].kind == 'sphere'
    assert human.visuals['body'][3].rgba == (0.9, 0.7, 0.55, 1.0)         # by name
    ball = parse_file('ball.urdf')
    assert ball.visuals['ball_link'][0].rgba == (0.0, 0.8, 0.0, 1.0)       # inline
    robot = parse_file('robot.urdf')
    wheel = robot.visuals['link_right_wheel'][0]
    pos, nrm = gl_meshes.visual_triangles(wheel)
    # rpy (1.5708, 0, 0) turns the cylinder's axis from z to -y: 4 cm wide in y
    assert np.ptp(pos[:, 1]) == pytest.approx(0.04, abs=1e-3)
    assert np.ptp(pos[:, 2]) == pytest.approx(0.2, abs=1e-3)


def test_obj_and_stl_loaders(tmp_path):
    pos, nrm = cube_obj(tmp_path / 'cube.obj')
    assert pos.shape == (36, 3)                          # 6 quads fanned into 12 triangles
    tri = pos.reshape(-1, 3, 3)
    winding = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    assert (np.einsum('ij,ij->i', winding, nrm[::3]) > 0).all()   # outward, like vn
    cube_stl(tmp_path / 'cube.stl', pos)
    spos, snrm = gl_meshes.load_stl(str(tmp_path / 'cube.stl'))
    np.testing.assert_allclose(spos, pos, atol=1e-6)
    np.testing.assert_allclose(snrm, nrm, atol=1e-6)      # normals from the winding
    ascii_ = ['solid cube'] + ['facet normal 0 0 0\nouter loop\n' + ''.join(
        'vertex %g %g %g\n' % tuple(c) for c in t) + 'endloop\nendfacet' for t in tri]
    (tmp_path / 'ascii.stl').write_text('\n'.join(ascii_) + '\nendsolid cube\n')
    apos, _ = gl_meshes.load_stl(str(tmp_path / 'ascii.stl'))
    np.testing.assert_allclose(apos, pos, atol=1e-6)


def test_mesh_paths_relative_and_package(tmp_path):
    (tmp_path / 'mypkg' / 'urdf').mkdir(parents=True)
    (tmp_path / 'mypkg' / 'meshes').mkdir()
    (tmp_path / 'mypkg' / 'meshes' / 'cube.obj').write_text('v 0 0 0\n')
    urdf_dir = str(tmp_path / 'mypkg' / 'urdf')
    want = str(tmp_path / 'mypkg' / 'meshes' / 'cube.obj')
    assert resolve_mesh_path('package://mypkg/meshes/cube.obj', urdf_dir) == want
    assert resolve_mesh_path('../meshes/cube.obj', urdf_dir) == os.path.join(
        urdf_dir, '../meshes/cube.obj')



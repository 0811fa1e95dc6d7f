"""Rotations and poses as numpy matrices (no ROS, no pybullet): URDF's
roll/pitch/yaw, (x, y, z, w) quaternions, 4x4 poses."""
import math

import numpy as np


def rpy_matrix(roll, pitch, yaw):
    """3x3 rotation of URDF fixed-axis roll/pitch/yaw: Rz(yaw) Ry(pitch) Rx(roll)."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch),
                              math.sin(pitch), math.cos(yaw), math.sin(yaw))
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def quaternion_matrices(q):
    """(n, 3, 3) rotations of (n, 4) unit (x, y, z, w) quaternions, vectorised."""
    x, y, z, w = np.asarray(q, float).reshape(-1, 4).T
    return np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                     2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                     2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
                    -1).reshape(-1, 3, 3)


def pose_matrix(position, orientation):
    """4x4 pose from a position and an (x, y, z, w) quaternion or a 3x3 rotation."""
    m, o = np.eye(4), np.asarray(orientation, float)
    m[:3, :3] = o if o.shape == (3, 3) else quaternion_matrices(o)[0]
    m[:3, 3] = position
    return m

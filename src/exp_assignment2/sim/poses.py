"""Poses as Gazebo's services take them: checked, composed, and named
entities (``model`` or ``model::link``) looked up (no ROS, no pybullet).

A pose is ((x, y, z), (qx, qy, qz, qw)). A message's all-zero quaternion
(a Pose whose orientation was never set) means no rotation, as Gazebo reads it.
"""
import math

import numpy as np

from exp_assignment2.sim.rotations import quaternion_matrices

WORLD_FRAMES = ('', 'world', 'map', '/world', '/map')
IDENTITY = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))

# Where a service may put a body: within the world's bounds and this margin
# (m); in a world without bounds (an SDF world), within MAX_COORDINATE of the
# origin. Beyond about 3.4e38 m pybullet's broadphase breaks for good: a body
# put there and back no longer touches the floor.
WORLD_MARGIN = 1.0
MAX_COORDINATE = 1.0e5
MAX_SPEED = 1.0e3       # m/s and rad/s: no body in these worlds moves faster


class PoseError(ValueError):
    """A pose or entity that cannot be used, with the reason."""


def _fmt(values):
    return '(%s)' % ', '.join('%.6g' % v for v in values)


def pose_tuple(msg):
    """((x, y, z), unit quaternion) of a geometry_msgs/Pose; PoseError if any
    value is not finite."""
    p, q = msg.position, msg.orientation
    position, quat = (p.x, p.y, p.z), (q.x, q.y, q.z, q.w)
    if not all(math.isfinite(v) for v in position + quat):
        raise PoseError('the pose %s %s is not finite' % (_fmt(position), _fmt(quat)))
    norm = math.sqrt(sum(v * v for v in quat))
    if norm < 1e-9:
        return position, IDENTITY[1]
    return position, tuple(v / norm for v in quat)


def twist_tuple(msg):
    """((vx, vy, vz), (wx, wy, wz)) of a geometry_msgs/Twist; PoseError if not
    finite or faster than MAX_SPEED."""
    lin, ang = msg.linear, msg.angular
    values = ((lin.x, lin.y, lin.z), (ang.x, ang.y, ang.z))
    if not all(math.isfinite(v) for part in values for v in part):
        raise PoseError('the twist %s %s is not finite' % (_fmt(values[0]), _fmt(values[1])))
    if any(abs(v) > MAX_SPEED for part in values for v in part):
        raise PoseError('the twist %s %s is faster than %g m/s or rad/s'
                        % (_fmt(values[0]), _fmt(values[1]), MAX_SPEED))
    return values


def world_region(bounds, margin, z_min=-MAX_COORDINATE):
    """(x_min, x_max, y_min, y_max, z_min, z_max): the world's bounds widened
    by ``margin``, +-MAX_COORDINATE where a bound is infinite."""
    widened = [b - margin if i % 2 == 0 else b + margin for i, b in enumerate(bounds)]
    return tuple(max(-MAX_COORDINATE, min(MAX_COORDINATE, v)) for v in widened) + (
        z_min, MAX_COORDINATE)


def in_region(region, position):
    x_min, x_max, y_min, y_max, z_min, z_max = region
    x, y, z = position
    return x_min <= x <= x_max and y_min <= y <= y_max and z_min <= z <= z_max


def check_in_world(bounds, position):
    """PoseError unless a service may put a body at ``position`` (see WORLD_MARGIN)."""
    region = world_region(bounds, WORLD_MARGIN)
    if not in_region(region, position):
        raise PoseError('the position %s is outside the world (x in [%g, %g], y in [%g, %g], '
                        'z in [%g, %g])' % ((_fmt(position),) + region))
    return position


def matrix(pose):
    m = np.eye(4)
    m[:3, :3] = quaternion_matrices(pose[1])[0]
    m[:3, 3] = pose[0]
    return m


def from_matrix(m):
    """((x, y, z), (qx, qy, qz, qw)) of a 4x4 rigid transform."""
    r = m[:3, :3]
    w = math.sqrt(max(0.0, 1.0 + r[0, 0] + r[1, 1] + r[2, 2])) / 2.0
    x = math.copysign(math.sqrt(max(0.0, 1.0 + r[0, 0] - r[1, 1] - r[2, 2])) / 2.0,
                      r[2, 1] - r[1, 2])
    y = math.copysign(math.sqrt(max(0.0, 1.0 - r[0, 0] + r[1, 1] - r[2, 2])) / 2.0,
                      r[0, 2] - r[2, 0])
    z = math.copysign(math.sqrt(max(0.0, 1.0 - r[0, 0] - r[1, 1] + r[2, 2])) / 2.0,
                      r[1, 0] - r[0, 1])
    return tuple(float(v) for v in m[:3, 3]), (x, y, z, w)


def rpy(quat):
    """(roll, pitch, yaw) of a unit quaternion (URDF's fixed axes)."""
    x, y, z, w = quat
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return roll, pitch, yaw


def split_entity(name):
    """('model', 'link' or None) of 'model' or 'model::link'."""
    model, _, link = name.partition('::')
    return model, (link or None)


def entity_pose(engine, name):
    """World pose of a named entity: a model, ``model::link``, or a bare link
    name (the first model that has it, as Gazebo's lookup by name)."""
    if name in WORLD_FRAMES:
        return IDENTITY
    model_name, link = split_entity(name)
    model = engine.models.get(model_name)
    if model is not None:
        if link is None:
            return model.pose()
        if link in model.body.links:
            return model.link_pose(link)
        raise PoseError('model %s has no link %r' % (model_name, link))
    for model in engine.models.values():
        if name in model.body.links:
            return model.link_pose(name)
    raise PoseError('there is no model or link named %r' % name)


def pose_in_world(engine, pose, reference):
    """``pose`` given in ``reference``'s frame, as (x, y, z, roll, pitch, yaw) in
    the world; PoseError outside it (:func:`check_in_world`)."""
    world = from_matrix(matrix(entity_pose(engine, reference)).dot(matrix(pose)))
    return tuple(check_in_world(engine.bounds, world[0])) + rpy(world[1])


def relative(engine, pose, reference):
    """A world ``pose`` expressed in ``reference``'s frame."""
    if reference in WORLD_FRAMES:
        return pose
    return from_matrix(np.linalg.inv(matrix(entity_pose(engine, reference))).dot(matrix(pose)))

"""Plane geometry shared by the simulator, the controllers and the tests (no ROS)."""
import math


def yaw_of(quat):
    """Yaw (rad) of an (x, y, z, w) quaternion."""
    x, y, z, w = quat
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def quaternion_from_yaw(yaw):
    """The (x, y, z, w) quaternion of a rotation by ``yaw`` about z."""
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


def normalize_angle(angle):
    """Wrap an angle to [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def clamp(value, limit):
    """``value`` limited to [-limit, limit]."""
    return max(-limit, min(limit, value))


def all_finite(*values):
    """True when every value is a finite number."""
    try:
        return all(math.isfinite(v) for v in values)
    except TypeError:
        return False


def cap_norm(vx, vy, limit):
    """(vx, vy) scaled down so that its length is at most ``limit``."""
    speed = math.hypot(vx, vy)
    if speed > limit > 0.0:
        scale = limit / speed        # vx * limit could overflow for vx near 1e308
        return vx * scale, vy * scale
    return vx, vy


def world_to_body(vx, vy, yaw):
    """A velocity (vx, vy) in the world frame, in the frame of a body whose
    heading is ``yaw``: what a planar drive that reads x, y in the body frame
    (Gazebo's planar_move) needs to move the body along (vx, vy)."""
    c, s = math.cos(yaw), math.sin(yaw)
    return c * vx + s * vy, -s * vx + c * vy

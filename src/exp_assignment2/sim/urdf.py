"""What the simulator reads from a URDF besides what pybullet loads (no ROS).

A Gazebo user's URDF carries its drive's wiring in a ``<gazebo><plugin>``
element (``libgazebo_ros_diff_drive.so``: leftJoint, rightJoint,
wheelSeparation, wheelDiameter, wheelTorque). The simulator honours it, so
swapping the URDF (``robot_model:=original``) swaps the wiring, as in Gazebo.
"""
import xml.etree.ElementTree as ET

DIFF_DRIVE_PLUGIN = 'libgazebo_ros_diff_drive.so'


def parse(urdf_text):
    """The URDF's root element; ValueError with the parser's reason."""
    try:
        root = ET.fromstring(urdf_text)
    except ET.ParseError as exc:
        raise ValueError('not a valid URDF: %s' % exc)
    if root.tag != 'robot':
        raise ValueError('not a URDF: the root element is <%s>, not <robot>' % root.tag)
    return root


def gazebo_diff_drive(root):
    """The diff-drive options a ``<gazebo>`` plugin declares, in this package's
    names (left_joint, right_joint, wheel_separation, wheel_radius,
    wheel_torque); {} when there is none."""
    for plugin in root.iter('plugin'):
        if plugin.get('filename') != DIFF_DRIVE_PLUGIN:
            continue
        found = {}
        for tag, key, conv in (('leftJoint', 'left_joint', str),
                               ('rightJoint', 'right_joint', str),
                               ('wheelSeparation', 'wheel_separation', float),
                               ('wheelDiameter', 'wheel_radius', lambda v: float(v) / 2.0),
                               ('wheelTorque', 'wheel_torque', float)):
            element = plugin.find(tag)
            if element is not None and element.text and element.text.strip():
                found[key] = conv(element.text.strip())
        return found
    return {}


def joint_origin(root, name):
    """(x, y, z) of joint ``name``'s origin in its parent link's frame."""
    for joint in root.iter('joint'):
        if joint.get('name') == name:
            origin = joint.find('origin')
            xyz = origin.get('xyz', '0 0 0') if origin is not None else '0 0 0'
            return tuple(float(v) for v in xyz.split())
    raise ValueError('the URDF has no joint %r' % name)


def diff_drive_turn_sign(root):
    """+1 when the diff-drive plugin's left joint is on the robot's left (+y),
    so +angular.z turns left (REP 103); -1 when wired the other way round."""
    drive = gazebo_diff_drive(root)
    if 'left_joint' not in drive or 'right_joint' not in drive:
        raise ValueError('no Gazebo diff-drive plugin with leftJoint and rightJoint')
    left_y = joint_origin(root, drive['left_joint'])[1]
    right_y = joint_origin(root, drive['right_joint'])[1]
    return 1 if left_y > right_y else -1

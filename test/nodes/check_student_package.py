#!/usr/bin/env python3
"""A student's whole package, launched as its user launches it (see
test/test_student_package.py): the robot stands where the launch file put
it, the world of its SDF file and its SDF crate are there, the camera has
the URDF's size and rate, the C++ node runs, the YAML's renamed controller
moves the head, and a turn goes the way the URDF's wheels say. The numbers
the launch file and the URDF give are this test's parameters."""
import math
import threading
import unittest
import xml.etree.ElementTree as ET

import numpy as np
import rospy
import rostest
from controller_manager_msgs.srv import ListControllers
from gazebo_msgs.msg import ModelStates
from gazebo_msgs.srv import GetModelState
from geometry_msgs.msg import Twist, Vector3
from sensor_msgs.msg import CameraInfo, Image, JointState
from std_msgs.msg import Float64

from checks import Watch, clock, wait_for_subscribers, wait_until
from exp_assignment2.geometry import yaw_of

START = 120.0       # ROS s for the launch file's models to appear


def angle_diff(a, b):
    return math.atan2(math.sin(a - b), math.cos(a - b))


def rpy_matrix(roll, pitch, yaw):
    cr, sr, cp, sp = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def expected_turn_sign(urdf_text):
    """The sign of the yaw rate a +angular.z gives, by the URDF's wheels as
    Noetic's diff drive drives them: wheel speed -w*s/2 on leftJoint and
    +w*s/2 on rightJoint (for w > 0, v = 0), each turning about its joint's
    axis. A wheel at lateral offset y rolling forward at u gives u = -w_z * y,
    so w_z = (u_left - u_right) / (y_right - y_left)."""
    root = ET.fromstring(urdf_text)
    plugin = [p for p in root.iter('plugin')
              if p.get('filename') == 'libgazebo_ros_diff_drive.so'][0]
    joints = {j.get('name'): j for j in root.iter('joint')}
    wheels = {}
    for tag, speed in (('leftJoint', -1.0), ('rightJoint', 1.0)):
        joint = joints[plugin.findtext(tag).strip()]
        origin = joint.find('origin')
        y = float(origin.get('xyz', '0 0 0').split()[1])
        rotation = rpy_matrix(*[float(v) for v in origin.get('rpy', '0 0 0').split()])
        axis = rotation.dot([float(v) for v in joint.find('axis').get('xyz').split()])
        forward = np.cross([0, 0, -1], axis)[0]     # ground speed per unit of joint rotation
        wheels[tag] = (speed * forward, y)
    (u_left, y_left), (u_right, y_right) = wheels['leftJoint'], wheels['rightJoint']
    return 1 if (u_left - u_right) / (y_right - y_left) > 0 else -1


class StudentPackageTest(unittest.TestCase):
    """In order: nothing drives the robot before its pose is checked."""

    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_student_package')
        clock()
        cls.p = {k: rospy.get_param('~' + k) for k in (
            'model', 'x', 'y', 'yaw', 'camera_width', 'camera_height', 'camera_rate',
            'controller', 'joint', 'world_models', 'crate')}
        cls.states = Watch('/gazebo/model_states', ModelStates)
        cls.joints = Watch('/robot/joint_states', JointState)
        cls.cmd = rospy.Publisher('/robot/cmd_vel', Twist, queue_size=1)
        cls.head = rospy.Publisher('/robot/%s/command' % cls.p['controller'], Float64,
                                   queue_size=1, latch=True)
        assert wait_until(lambda: cls.states.msg is not None and cls.p['model'] in
                          cls.states.msg.name, START), 'no %s in /gazebo/model_states' % (
            cls.p['model'])

    def pose_of(self, name):
        msg = self.states.next()
        pose = msg.pose[msg.name.index(name)]
        q = pose.orientation
        return pose.position.x, pose.position.y, yaw_of((q.x, q.y, q.z, q.w))

    def test_1_the_robot_stands_where_the_launch_file_put_it(self):
        rospy.wait_for_service('/gazebo/get_model_state', timeout=30)
        state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)(self.p['model'], '')
        self.assertTrue(state.success, state.status_message)
        q = state.pose.orientation
        self.assertAlmostEqual(state.pose.position.x, self.p['x'], delta=0.05)
        self.assertAlmostEqual(state.pose.position.y, self.p['y'], delta=0.05)
        self.assertAlmostEqual(angle_diff(yaw_of((q.x, q.y, q.z, q.w)), self.p['yaw']), 0,
                               delta=0.05)

    def test_2_the_sdf_world_and_the_sdf_crate_are_there(self):
        wanted = set(self.p['world_models']) | {'crate'}
        self.assertTrue(wait_until(lambda: wanted <= set(self.states.msg.name), 30),
                        'missing: %s' % sorted(wanted - set(self.states.msg.name)))
        x, y, _ = self.pose_of('crate')
        self.assertAlmostEqual(x, self.p['crate'][0], delta=0.1)
        self.assertAlmostEqual(y, self.p['crate'][1], delta=0.1)

    def test_3_the_camera_has_the_urdfs_size_and_rate(self):
        stamps, lock = [], threading.Lock()

        def on_image(msg):
            with lock:
                stamps.append((msg.header.stamp.to_sec(), msg.width, msg.height,
                               msg.encoding))
            clock().notify()
        sub = rospy.Subscriber('/robot/camera1/image_raw', Image, on_image, queue_size=100)
        info = Watch('/robot/camera1/camera_info', CameraInfo)
        try:
            self.assertTrue(wait_until(lambda: len(stamps) >= 1, 30), 'no camera image')
            first = stamps[0][0]
            self.assertTrue(wait_until(lambda: stamps[-1][0] - first >= 4.0, 30))
        finally:
            sub.unregister()
        with lock:
            frames = list(stamps)
        self.assertEqual({f[1:] for f in frames},
                         {(self.p['camera_width'], self.p['camera_height'], 'rgb8')})
        rate = (len(frames) - 1) / (frames[-1][0] - frames[0][0])
        self.assertAlmostEqual(rate, self.p['camera_rate'], delta=1.0)
        camera = info.next()
        self.assertEqual((camera.width, camera.height),
                         (self.p['camera_width'], self.p['camera_height']))

    def test_4_the_students_cpp_node_runs(self):
        got, lock = [], threading.Lock()

        def on_beat(msg):
            with lock:
                got.append(msg._connection_header['type'])
            clock().notify()
        sub = rospy.Subscriber('/heartbeat', rospy.AnyMsg, on_beat)
        try:
            self.assertTrue(wait_until(lambda: len(got) >= 2, 10), 'no heartbeat from the '
                            'C++ node in 10 s')
        finally:
            sub.unregister()
        self.assertEqual(set(got), {'exp_assignment2/Heartbeat'})   # the package's own message

    def test_5_the_yamls_controllers_run_under_their_names(self):
        rospy.wait_for_service('/robot/controller_manager/list_controllers', timeout=30)
        listing = rospy.ServiceProxy('/robot/controller_manager/list_controllers',
                                     ListControllers)
        self.joints.next(30)
        running = {c.name: c.state for c in listing().controller}
        self.assertEqual(running.get(self.p['controller']), 'running', running)
        self.assertEqual(running.get('joint_state_controller'), 'running', running)

    def test_6_the_renamed_controller_moves_the_head(self):
        joint = self.p['joint']
        wait_for_subscribers(self.head)
        for target in (0.6, -0.4):
            self.head.publish(Float64(target))
            self.assertTrue(wait_until(lambda: joint in self.joints.msg.name and abs(
                self.joints.msg.position[self.joints.msg.name.index(joint)] - target) < 0.05,
                10), '%s did not reach %.2f' % (joint, target))

    def test_7_a_turn_goes_the_way_the_urdfs_wheels_say(self):
        sign = expected_turn_sign(rospy.get_param('/robot/robot_description'))
        wait_for_subscribers(self.cmd)
        _, _, before = self.pose_of(self.p['model'])
        turn = rospy.Timer(rospy.Duration(0.05),
                           lambda _e: self.cmd.publish(Twist(angular=Vector3(z=0.6))))
        try:
            start = rospy.get_time()
            wait_until(lambda: rospy.get_time() - start >= 2.0, 10)
        finally:
            turn.shutdown()
            self.cmd.publish(Twist())
        _, _, after = self.pose_of(self.p['model'])
        turned = angle_diff(after, before)
        self.assertGreater(abs(turned), 0.3, 'the robot turned %.2f rad' % turned)
        self.assertEqual(1 if turned > 0 else -1, sign,
                         'turned %.2f rad; the URDF says %+d' % (turned, sign))


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'student_package', StudentPackageTest)

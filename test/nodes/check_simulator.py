#!/usr/bin/env python3
"""The simulator does what Gazebo did: camera content and intrinsics, diff
drive by REP 103, limits, timeouts, the head, the ball's height, reset,
pause, and a clock faster than the wall. Each test asks one question."""
import math
import time
import unittest

import rospy
import rostest
import tf2_ros
from gazebo_msgs.msg import LinkState
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import CameraInfo, CompressedImage, Image, JointState
from std_msgs.msg import Float64
from std_srvs.srv import Empty
from visualization_msgs.msg import MarkerArray

from checks import (Pose, Rosout, Watch, clock, eventually, node_pid, wait_for_subscribers,
                    wait_until)
from exp_assignment2.geometry import yaw_of
from exp_assignment2.sim import urdf
from exp_assignment2.vision import BallDetector, decode_jpeg

SPAWN = (-5.0, 7.0, math.pi)


def ball_in(msg):
    return BallDetector().detect(decode_jpeg(msg.data))


def angle_diff(a, b):
    return math.atan2(math.sin(a - b), math.cos(a - b))


class TestSimulator(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_simulator')
        clock()
        for srv in ('/gazebo/reset_world', '/gazebo/pause_physics'):
            rospy.wait_for_service(srv, timeout=30)
        cls.reset = rospy.ServiceProxy('/gazebo/reset_world', Empty)
        cls.pause = rospy.ServiceProxy('/gazebo/pause_physics', Empty)
        cls.unpause = rospy.ServiceProxy('/gazebo/unpause_physics', Empty)
        cls.cmd = rospy.Publisher('/robot/cmd_vel', Twist, queue_size=1)
        cls.head = rospy.Publisher('/robot/joint_position_controller/command', Float64,
                                   queue_size=1)
        cls.link_state = rospy.Publisher('/gazebo/set_link_state', LinkState, queue_size=1)
        cls.odom, cls.ball = Pose('/robot/odom'), Pose('/ball/odom')
        cls.joints = Watch('/robot/joint_states', JointState)
        cls.image = Watch('/robot/camera1/image_raw/compressed', CompressedImage)
        cls.info = Watch('/robot/camera1/camera_info', CameraInfo)
        cls.rosout = Rosout()
        cls.tf = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf)
        for pub in (cls.cmd, cls.head, cls.link_state):
            wait_for_subscribers(pub)
        cls.image.next(30)

    def setUp(self):
        # a command of the test before still on its way would drive the reset robot
        self.cmd.publish(Twist())
        self.assertTrue(self.at_rest(), 'the robot does not come to rest')
        self.reset()
        self.assertTrue(self.back_at_spawn(), 'pose after the reset: %s' % (self.odom.xyzyaw(),))

    def at_rest(self, seconds=0.6, ros_seconds=10.0):
        """Wait until odometry has shown the robot still for ``seconds`` of its
        stamps (longer than the drive's 0.5 s command timeout: a command that
        was late would have moved it). The odometry stamped then, or None."""
        odom = Watch('/robot/odom', Odometry, keep=True)
        still = []

        def rested():
            while odom.all:
                msg = odom.all.pop(0)
                t = msg.twist.twist
                if math.hypot(t.linear.x, t.linear.y) > 0.005 or abs(t.angular.z) > 0.01:
                    del still[:]
                else:
                    still.append(msg)
            return still and (still[-1].header.stamp - still[0].header.stamp).to_sec() >= seconds
        try:
            return still[-1] if eventually(rested, ros_seconds) else None
        finally:
            odom.sub.unregister()

    def back_at_spawn(self):
        """After a reset: an odometry message published before it may still be
        on its way when the service answers, so wait for one at the spawn pose."""
        def at_spawn():
            x, y, _, yaw = self.odom.xyzyaw()
            return (math.hypot(x - SPAWN[0], y - SPAWN[1]) < 0.02
                    and abs(angle_diff(yaw, SPAWN[2])) < 0.02)
        return eventually(at_spawn, ros_seconds=1.0)

    def drive(self, linear, angular, seconds, until=None):
        """Publish a command at 20 Hz of simulated time for ``seconds``, or
        (``until``) until ``until()`` holds, at most ``seconds``: at
        real_time_factor 0 a checker kept off its CPU misses its beats and the
        drive's command timeout stops the robot in between, so a distance is
        waited for rather than a duration."""
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        end = rospy.get_time() + seconds
        while rospy.get_time() < end and not (until is not None and until()):
            self.cmd.publish(twist)
            clock().sleep(0.05)

    def pose(self):
        self.odom.next()
        return self.odom.xyzyaw()

    def test_odometry_and_camera_keep_their_rates_in_simulated_time(self):
        # what hztest measured, without a launch of its own for each rate:
        # messages published per simulated second, from sequence numbers and
        # stamps (one dropped on its way on a loaded machine is not a lower rate)
        streams = {'/robot/odom': (Odometry, float(rospy.get_param('~odom_hz'))),
                   '/robot/camera1/image_raw/compressed': (CompressedImage, 30.0)}
        watches = {topic: Watch(topic, cls, keep=True) for topic, (cls, _) in streams.items()}
        try:
            def spans():      # s of stamps each stream has brought so far
                return [w.all[-1].header.stamp.to_sec() - w.all[0].header.stamp.to_sec()
                        if w.all else 0.0 for w in watches.values()]
            self.assertTrue(eventually(lambda: min(spans()) >= 5.0, 30.0, 30.0),
                            'not 5 s of both streams: %s s of %s messages' % (
                                spans(), [len(w.all) for w in watches.values()]))
            for topic, (_, hz) in streams.items():
                first, last = watches[topic].all[0].header, watches[topic].all[-1].header
                rate = (last.seq - first.seq) / (last.stamp.to_sec() - first.stamp.to_sec())
                rospy.loginfo('%s at %.2f Hz of simulated time', topic, rate)
                self.assertAlmostEqual(rate, hz, delta=0.5, msg=topic)
        finally:
            for watch in watches.values():
                watch.sub.unregister()

    def test_camera_sees_the_ball_in_front(self):
        ball = ball_in(self.image.next())
        self.assertIsNotNone(ball, 'the ball at (-7, 6) is in front of the robot at spawn')
        self.assertGreater(ball.radius, 50)

    def set_ball_height(self, z):
        """As the original's ball server: /gazebo/set_link_state on ball_link."""
        x, y, _, _ = self.ball.xyzyaw()
        state = LinkState(link_name='ball_link')
        state.pose.position.x, state.pose.position.y, state.pose.position.z = x, y, z
        self.link_state.publish(state)

    def test_a_ball_under_the_ground_or_20_m_up_is_not_seen(self):
        for z in (-1.0, 20.0):
            self.set_ball_height(z)
            self.assertTrue(wait_until(lambda: abs(self.ball.msg.pose.pose.position.z - z)
                                       < 1e-6, 5.0))
            moved = self.ball.msg.header.stamp.to_sec()
            self.assertIsNone(ball_in(self.image.after(moved)), 'ball at z = %g' % z)
        self.set_ball_height(0.5)
        self.assertTrue(wait_until(lambda: self.ball.msg.pose.pose.position.z == 0.5, 5.0))
        self.assertIsNotNone(ball_in(self.image.after(self.ball.msg.header.stamp.to_sec())))

    def test_rviz_sees_the_walls_the_person_the_kennel_and_the_grid(self):
        markers = Watch('/gazebo/world_markers', MarkerArray).next(10.0)
        spaces = {m.ns for m in markers.markers}
        self.assertTrue({'arena', 'human', 'kennel', 'grid'} <= spaces, spaces)
        self.assertNotIn('robot', spaces)           # robots are shown by their descriptions
        walls = [m for m in markers.markers if m.ns == 'arena' and m.scale.z == 1.0]
        self.assertEqual(sorted(round(abs(m.pose.position.x) + abs(m.pose.position.y), 1)
                                for m in walls), [9.4] * 4)
        self.assertTrue(all(m.header.frame_id == 'odom' for m in markers.markers[1:]))

    def test_the_raw_image_is_rgb8_with_the_stamp_and_frame_of_the_jpeg(self):
        raw = Watch('/robot/camera1/image_raw', Image, keep=True)
        jpegs = Watch('/robot/camera1/image_raw/compressed', CompressedImage, keep=True)

        def matched():      # raw frames with the stamp and frame of a JPEG one
            stamps = {(m.header.stamp, m.header.frame_id) for m in list(jpegs.all)}
            return [m for m in list(raw.all) if (m.header.stamp, m.header.frame_id) in stamps]
        try:     # 1.9 MB a frame: the simulator stops drawing them once we leave
            # (each subscription connects in its own time: wait for frames of both)
            ok = eventually(lambda: len(matched()) >= 3)
        finally:
            raw.sub.unregister()
            jpegs.sub.unregister()
        self.assertTrue(ok, 'raw %s, jpeg %s' % (
            ['%.2f' % m.header.stamp.to_sec() for m in raw.all[-8:]],
            ['%.2f' % m.header.stamp.to_sec() for m in jpegs.all[-8:]]))
        image = raw.all[-1]
        self.assertEqual((image.width, image.height, image.encoding, image.step),
                         (800, 800, 'rgb8', 2400))
        self.assertEqual(image.header.frame_id, 'camera_link')

    def test_camera_info_is_an_800_px_pinhole_with_80_degrees(self):
        info = self.info.next()
        self.assertEqual((info.width, info.height), (800, 800))
        self.assertAlmostEqual(info.K[0], 800 / (2 * math.tan(1.3962634 / 2)), places=6)
        self.assertEqual((info.K[2], info.K[5]), (400.0, 400.0))
        self.assertEqual(info.header.frame_id, 'camera_link')

    def test_positive_angular_z_turns_as_the_robot_model_is_wired(self):
        sign = rospy.get_param('/robot/turn_sign')     # rep103: +1 (left), original: -1
        self.assertEqual(sign, rospy.get_param('~turn_sign'))
        yaw0 = self.pose()[3]
        self.drive(0.0, 0.5, 10.0, until=lambda: abs(angle_diff(self.odom.xyzyaw()[3], yaw0))
                   > 0.3)
        self.assertGreater(sign * angle_diff(self.pose()[3], yaw0), 0.15)

    def test_forward_command_moves_along_the_heading(self):
        x0, y0, _, yaw0 = self.pose()
        during = Watch('/robot/odom', Odometry, keep=True)
        try:
            self.drive(0.4, 0.0, 10.0, until=lambda: math.hypot(
                self.odom.xyzyaw()[0] - x0, self.odom.xyzyaw()[1] - y0) > 0.7)
        finally:
            during.sub.unregister()
        x1, y1, _, _ = self.pose()
        along = (x1 - x0) * math.cos(yaw0) + (y1 - y0) * math.sin(yaw0)
        across = -(x1 - x0) * math.sin(yaw0) + (y1 - y0) * math.cos(yaw0)
        self.assertGreater(along, 0.5)
        self.assertLess(abs(across), 0.1)
        # while driving (after it, a late last command may have timed out):
        # heading pi, so a world-frame twist would be -0.4
        self.assertGreater(max(m.twist.twist.linear.x for m in during.all), 0.3,
                           'odom twist is in the child frame')

    def test_a_stale_command_stops_the_robot(self):
        x0, y0, _, _ = self.pose()
        self.drive(0.4, 0.0, 10.0, until=lambda: math.hypot(
            self.odom.xyzyaw()[0] - x0, self.odom.xyzyaw()[1] - y0) > 0.1)
        # no more commands: the 0.5 s timeout stops the wheels, and the robot
        # stays where it stopped
        rest = self.at_rest(seconds=1.0)
        self.assertIsNotNone(rest, 'the robot went on without commands')
        p = rest.pose.pose.position
        self.assertGreater(math.hypot(p.x - x0, p.y - y0), 0.1)

    def test_a_non_finite_command_is_ignored_with_a_warning(self):
        x0, y0, _, _ = self.pose()
        twist = Twist()
        twist.linear.x, twist.angular.z = float('nan'), float('inf')
        for _ in range(5):
            self.cmd.publish(twist)
            clock().sleep(0.1)
        x1, y1, _, _ = self.pose()
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 0.02)
        self.assertTrue(wait_until(lambda: self.rosout.lines('not finite', Log.WARN), 5.0))

    def test_a_huge_command_is_clamped_to_2_m_per_s(self):
        x0, y0, _, _ = self.pose()
        self.drive(1.0e308, 0.0, 1.0)
        x1, y1, z1, yaw1 = self.pose()
        self.assertTrue(all(math.isfinite(v) for v in (x1, y1, z1, yaw1)))
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 2.0 * 1.1)
        self.assertTrue(wait_until(lambda: self.rosout.lines('clamped', Log.WARN), 5.0))

    def test_the_head_follows_its_command_and_is_clamped(self):
        def head():
            msg = self.joints.next()
            return msg.position[msg.name.index('head_joint')]
        self.head.publish(Float64(0.6))
        clock().sleep(1.5)
        self.assertAlmostEqual(head(), 0.6, delta=0.03)
        upper = urdf.parse(rospy.get_param('/robot/robot_description')).joints[
            'head_joint'].upper
        self.head.publish(Float64(upper + 1.0))
        clock().sleep(3.0)
        self.assertAlmostEqual(head(), upper, delta=0.03)
        self.head.publish(Float64(0.0))
        clock().sleep(1.5)

    def test_tf_has_the_camera_and_its_yaw_follows_the_head(self):
        frame = self.info.next().header.frame_id
        def head_at(angle):
            msg = self.joints.msg
            return abs(msg.position[msg.name.index('head_joint')] - angle) < 0.01
        for angle in (0.6, -0.6, 0.0):
            self.head.publish(Float64(angle))
            # the command takes wall time to arrive: many simulated s at rtf 0
            self.assertTrue(eventually(lambda: head_at(angle)), 'the head never got to %g' % angle)
            # robot_state_publisher turns joint states into TF in its own
            # process: on a loaded machine its frames may lag the joint states
            seen = []

            def camera_follows():
                msg = self.odom.msg
                camera = self.tf.lookup_transform('odom', frame, msg.header.stamp)
                q, p = camera.transform.rotation, msg.pose.pose.orientation
                seen.append(angle_diff(yaw_of((q.x, q.y, q.z, q.w)),
                                       yaw_of((p.x, p.y, p.z, p.w))))
                return abs(seen[-1] - angle) < 0.03

            def settled():
                try:
                    return camera_follows()
                except tf2_ros.TransformException:
                    return False
            ok = eventually(settled)
            rospy.loginfo('head commanded %+.2f rad: camera yaw - robot yaw = %s rad',
                          angle, ', '.join('%+.3f' % a for a in seen[-3:]))
            self.assertTrue(ok, 'camera yaw - robot yaw: %s' % seen[-3:])

    def test_reset_puts_the_robot_back(self):
        self.drive(0.5, 0.3, 10.0, until=lambda: math.hypot(
            self.odom.xyzyaw()[0] - SPAWN[0], self.odom.xyzyaw()[1] - SPAWN[1]) > 0.4)
        x, y, _, _ = self.pose()
        self.assertGreater(math.hypot(x - SPAWN[0], y - SPAWN[1]), 0.3)
        self.reset()
        self.assertTrue(self.back_at_spawn(), 'pose after the reset: %s' % (self.odom.xyzyaw(),))

    def test_pause_stops_the_clock(self):
        self.pause()
        try:
            # /clock messages sent before the pause (and the step under way)
            # may still be on their way: from then on the clock stands still
            time.sleep(0.5)
            t0 = rospy.get_time()
            time.sleep(0.5)
            self.assertEqual(rospy.get_time(), t0)
        finally:
            self.unpause()

    def test_as_fast_as_possible_leaves_the_other_nodes_their_cpu(self):
        pid = node_pid('/gazebo')
        with open('/proc/%d/stat' % pid) as f:
            nice = int(f.read().rsplit(')', 1)[1].split()[16])
        self.assertEqual(nice, 5)

    def test_the_clock_runs_faster_than_wall_time(self):
        t0, w0 = rospy.get_time(), time.monotonic()
        time.sleep(2.0)
        ratio = (rospy.get_time() - t0) / (time.monotonic() - w0)
        rospy.loginfo('simulated / wall time: %.2f', ratio)
        self.assertGreater(ratio, 1.0)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_simulator', TestSimulator)

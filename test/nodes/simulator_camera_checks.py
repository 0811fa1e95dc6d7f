"""The camera checks of check_simulator.py (a mixin of its test class, which
has the watches and publishers they use: one launch of the simulator for all):
rates in simulated time, what the camera sees, the raw image, camera_info,
the world for rviz, TF following the head."""
import math

import rospy
import tf2_ros
from gazebo_msgs.msg import LinkState
from nav_msgs.msg import Odometry
from sensor_msgs.msg import CompressedImage, Image
from std_msgs.msg import Float64
from visualization_msgs.msg import MarkerArray

from checks import Watch, eventually, wait_until
from exp_assignment2.geometry import yaw_of
from exp_assignment2.vision import BallDetector, decode_jpeg


def ball_in(msg):
    return BallDetector().detect(decode_jpeg(msg.data))


def camera_px():
    """The camera's width and height (the URDF's 800 px, unless the .test says)."""
    return int(rospy.get_param('~camera_px', 800))


def angle_diff(a, b):
    return math.atan2(math.sin(a - b), math.cos(a - b))


class CameraChecks(object):
    """Needs ``self.image``, ``info``, ``joints``, ``odom``, ``ball``, ``head``,
    ``link_state`` and ``tf`` (set up by the test class)."""

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
        self.assertGreater(ball.radius, 50 * camera_px() / 800.0)

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
        px = camera_px()
        self.assertEqual((image.width, image.height, image.encoding, image.step),
                         (px, px, 'rgb8', 3 * px))
        self.assertEqual(image.header.frame_id, 'camera_link')

    def test_camera_info_is_a_pinhole_of_its_size_with_80_degrees(self):
        info, px = self.info.next(), camera_px()
        self.assertEqual((info.width, info.height), (px, px))
        self.assertAlmostEqual(info.K[0], px / (2 * math.tan(1.3962634 / 2)), places=6)
        self.assertEqual((info.K[2], info.K[5]), (px / 2.0, px / 2.0))
        self.assertEqual(info.header.frame_id, 'camera_link')

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

#!/usr/bin/env python3
"""Empty and garbage CompressedImage frames among the camera's: each node
that decodes them (state_machine, robot_to_ball, image_decompress) logs one
WARN naming the topic (at most two lines: the first and the count), no error
and no traceback, keeps running and keeps decoding the real frames."""
import time
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import CompressedImage, Image

from checks import DogObserver, Watch, clock, wait_for_subscribers, wait_until
from system_checks import node_pid, wait_for_graph

TOPIC = '/robot/camera1/image_raw/compressed'
DECODERS = ('/state_machine', '/robot_to_ball', '/image_decompress')
BAD = (b'', b'garbage, not a JPEG image', b'\xff\xd8\xff\xe0' + b'\x00' * 40)


class TestCameraFrames(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_camera_frames')
        clock()
        cls.dog = DogObserver()
        cls.rosout = cls.dog.rosout
        cls.raw = Watch('/robot/camera1/image_decompressed', Image)   # image_decompress works
        cls.frames = rospy.Publisher(TOPIC, CompressedImage, queue_size=10)

    def test_bad_frames_are_one_warning_per_node_and_nothing_breaks(self):
        wait_for_subscribers(self.frames)
        self.assertTrue(wait_until(lambda: self.raw.msg is not None, 30.0), 'no decompressed image')
        self.assertTrue(wait_until(lambda: self.dog.state() is not None, 30.0))
        for name in DECODERS:
            wait_for_graph(TOPIC, name)
        pids = {name: node_pid(name) for name in DECODERS}
        self.assertNotIn(None, pids.values(), pids)
        for i in range(30):                     # 3 s of wall time, among the real frames
            msg = CompressedImage(format='rgb8; jpeg compressed bgr8', data=BAD[i % 3])
            msg.header.stamp = rospy.Time.now()
            self.frames.publish(msg)
            time.sleep(0.1)
        time.sleep(1.0)
        for name in DECODERS:
            warned = self.rosout.lines('not a JPEG image', Log.WARN, name)
            rospy.loginfo('%s: %d warning lines: %s', name, len(warned),
                          [m.msg for m in warned])
            self.assertTrue(1 <= len(warned) <= 2, '%s: %d lines' % (name, len(warned)))
            self.assertTrue(warned[0].msg.startswith(TOPIC + ': '), warned[0].msg)
            self.assertEqual(self.rosout.lines(level=Log.ERROR, node=name), [])
        self.assertEqual({name: node_pid(name) for name in DECODERS}, pids, 'a node restarted')
        count = self.raw.count
        self.assertTrue(wait_until(lambda: self.raw.count > count + 5, 10.0),
                        'image_decompress stopped decoding')


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_camera_frames', TestCameraFrames)

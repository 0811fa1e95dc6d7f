#!/usr/bin/env python3
"""Scenario B from the shell's point of view: a person's /voice and /gesture
take MiRo through SLEEP -> NORMAL -> PLAY -> NORMAL; every commanded grid point
is reached within 0.2 m; bad commands change nothing; the robot stays on the grid."""
import math
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64MultiArray, String
from std_srvs.srv import Empty

from dog_checks import wait_until
from exp_assignment2.msg import Gesture

PERSON, POINT, SAID = (5, 5), (8, 2), (1, 9)


class TestMiro(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_miro')
        cls.states, cls.arrivals, cls.commands, cls.xs, cls.ys = [], [], [], [], []
        rospy.Subscriber('/state', String, lambda m: cls.states.append(m.data), queue_size=50)
        rospy.Subscriber('/arrival', Float64MultiArray,
                         lambda m: cls.arrivals.append(list(m.data)), queue_size=50)
        rospy.Subscriber('/command', String, lambda m: cls.commands.append(m.data),
                         queue_size=50)
        rospy.Subscriber('/odom', Odometry, cls._on_odom, queue_size=10)
        cls.voice = rospy.Publisher('/voice', String, queue_size=10)
        cls.gesture = rospy.Publisher('/gesture', Gesture, queue_size=10, latch=True)
        cls.command = rospy.Publisher('/command', String, queue_size=10)
        # the world starts paused: run it once the state manager is up
        rospy.wait_for_message('/state', String, timeout=60)
        rospy.wait_for_service('/gazebo/unpause_physics', timeout=60)
        rospy.ServiceProxy('/gazebo/unpause_physics', Empty)()

    @classmethod
    def _on_odom(cls, msg):
        cls.xs.append(msg.pose.pose.position.x)
        cls.ys.append(msg.pose.pose.position.y)

    def arrived_at(self, x, y, after=0):
        return [a for a in self.arrivals[after:] if (a[0], a[1]) == (x, y)]

    def say(self, text):
        while self.voice.get_num_connections() == 0:
            rospy.sleep(0.05)
        self.voice.publish(String(text))

    def test_voice_and_gesture_drive_the_states(self):
        self.assertTrue(wait_until(lambda: self.states[:1] == ['SLEEP STATE'], 20.0))
        self.assertTrue(wait_until(lambda: self.arrived_at(3, 3), 60.0), 'never got home')
        self.gesture.publish(Gesture(person_x=PERSON[0], person_y=PERSON[1],
                                     point_x=POINT[0], point_y=POINT[1]))
        self.assertTrue(wait_until(lambda: 'NORMAL' in self.states, 30.0))
        # bad input: each gets a log line and changes nothing
        for text in ('go to 11 3', 'fly', 'go to -1 2', 'go to 2.5 3', ''):
            self.say(text)
        self.command.publish(String('go to 4'))
        self.gesture.publish(Gesture(person_x=-3, person_y=5, point_x=2, point_y=2))
        self.gesture.publish(Gesture(person_x=PERSON[0], person_y=PERSON[1],
                                     point_x=POINT[0], point_y=POINT[1]))
        rospy.sleep(1.0)
        self.assertEqual(self.states[-1], 'NORMAL')
        self.say('hey buddy')
        self.assertTrue(wait_until(lambda: self.states[-1] == 'PLAY STATE', 60.0),
                        'states %s' % self.states)
        n = len(self.arrivals)
        self.assertTrue(wait_until(lambda: self.arrived_at(*PERSON, after=n), 60.0),
                        'never came to the person; commands %s' % self.commands)
        self.say('go to %d %d' % SAID)
        self.assertTrue(wait_until(lambda: self.arrived_at(*SAID, after=n), 60.0),
                        'did not obey the voice; commands %s' % self.commands)
        # second loop: back to the person, then silence -> follow the pointing
        self.assertTrue(wait_until(lambda: self.arrived_at(*POINT, after=n), 60.0),
                        'did not follow the gesture; commands %s' % self.commands)
        self.assertTrue(wait_until(lambda: self.states[-1] == 'NORMAL', 30.0))
        self.assertEqual(self.states[:4], ['SLEEP STATE', 'NORMAL', 'PLAY STATE', 'NORMAL'])
        self.assertEqual(rospy.get_param('/state'), 'NORMAL')
        for target_x, target_y, x, y, _ in self.arrivals:
            self.assertLess(math.hypot(target_x - x, target_y - y), 0.2)
        self.assertGreaterEqual(min(self.xs + self.ys), -0.2)
        self.assertLessEqual(max(self.xs + self.ys), 10.2)
        self.assertNotIn('go to 11 3', self.commands)
        self.assertEqual(rospy.get_param('/arrived'), 1)
        self.assertEqual(len(rospy.get_param('/all')), 5)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_miro', TestMiro)

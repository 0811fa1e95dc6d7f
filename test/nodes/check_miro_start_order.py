#!/usr/bin/env python3
"""The MiRo world sets none of the parameters a user's nodes set, and a user's
nodes started in the original's order on it reach their targets.

Started after the world alone: it checks that /arrived, /home_posx, /home_posy
and /state are not set, then starts the user's state manager (rosrun), waits
until it is waiting for /arrived, and only then their launch file
(test/fixtures/miro_original/miro_user.launch: it sets /arrived and the home,
and starts the grounding, the motion controller and the print-info node).
"""
import math
import os
import signal
import subprocess
import time
import unittest

import rospkg
import rospy
import rostest
from nav_msgs.msg import Odometry

from checks import Watch, clock, wait_until

USERS_PARAMETERS = ('/arrived', '/home_posx', '/home_posy', '/state')


def wall_wait(predicate, seconds):
    deadline = time.time() + seconds
    while time.time() < deadline:
        if predicate():
            return True
        time.sleep(0.1)
    return False


class TestMiroStartOrder(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_miro_start_order')
        clock()
        cls.odom = Watch('/odom', Odometry)
        cls.started, cls.arrivals = [], []

    @classmethod
    def tearDownClass(cls):
        for proc in cls.started:
            if proc.poll() is None:
                proc.send_signal(signal.SIGINT)
        for proc in cls.started:
            try:
                proc.wait(20)
            except subprocess.TimeoutExpired:
                proc.kill()

    def arrival(self):
        report = rospy.get_param('/all', None)
        if report and (not self.arrivals or report[4] != self.arrivals[-1][4]):
            self.arrivals.append(report)
        return len(self.arrivals)

    def test_the_world_sets_nothing_and_nodes_started_in_the_original_order_arrive(self):
        self.odom.next(30.0)
        self.assertEqual([p for p in USERS_PARAMETERS if rospy.has_param(p)], [],
                         'the world alone must set none of the user\'s parameters')
        self.started.append(subprocess.Popen(['rosrun', 'exp_assignment2',
                                              'miro_state_manager.py']))
        # it sets /state on entering SLEEP, then waits for /arrived
        self.assertTrue(wall_wait(lambda: rospy.has_param('/state'), 60.0),
                        'the state manager never started')
        time.sleep(1.0)
        launch = os.path.join(rospkg.RosPack().get_path('exp_assignment2'), 'test', 'fixtures',
                              'miro_original', 'miro_user.launch')
        self.started.append(subprocess.Popen(['roslaunch', launch]))
        self.assertTrue(wait_until(lambda: self.arrival() >= 3, 300.0),
                        'arrivals: %s' % self.arrivals)
        self.assertEqual(self.arrivals[0][:2], [3, 3])
        for target_x, target_y, x, y, number in self.arrivals:
            rospy.loginfo('arrival %d: target (%d, %d), MiRo at (%.2f, %.2f)',
                          number, target_x, target_y, x, y)
            self.assertLess(math.hypot(target_x - x, target_y - y), 0.05)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_miro_start_order', TestMiroStartOrder)

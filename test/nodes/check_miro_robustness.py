#!/usr/bin/env python3
"""Scenario B as a hostile user would treat it: floods of bad words, orders
and gestures give a few short lines; a huge /cmd_vel cannot put MiRo off its
grid or make its pose non-finite, and MiRo still arrives where it is sent;
a motion controller that dies in the middle of a move comes back and drives
on to the same target, counting arrivals on."""
import math
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from std_msgs.msg import Float64MultiArray, Int64MultiArray, String
from std_srvs.srv import Empty

from checks import Pose, Rosout, Watch, clock, eventually, wait_for_subscribers, wait_until
from system_checks import kill_node, node_pid, wait_for_every_subscriber, world_held
from exp_assignment2.msg import Gesture

BURST = 1000


class TestMiroRobustness(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_miro_robustness')
        clock()
        cls.rosout, cls.odom = Rosout(), Pose('/odom')
        cls.arrivals = Watch('/arrival', Float64MultiArray, keep=True)
        cls.pubs = {topic: rospy.Publisher(topic, cls_, queue_size=BURST + 10) for topic, cls_
                    in (('/voice', String), ('/command', String), ('/gesture', Gesture),
                        ('/cmd_vel', Twist))}
        for pub in cls.pubs.values():
            wait_for_subscribers(pub)

    def test_1_floods_of_bad_input_make_a_few_short_lines(self):
        for i in range(BURST):
            self.pubs['/voice'].publish(String('go to %d 99' % i))
            self.pubs['/command'].publish(String('go_nowhere %d' % i))
            self.pubs['/gesture'].publish(Gesture(person_x=-i, person_y=0, point_x=1,
                                                  point_y=1))
        with world_held():                      # throttling is in wall time
            time.sleep(3.0)
        for topic in ('/voice', '/command', '/gesture'):
            lines = self.rosout.lines(topic + ':')
            rospy.loginfo('%s: %d bad messages gave %d lines', topic, BURST, len(lines))
            self.assertTrue(2 <= len(lines) <= 15, '%s: %d lines' % (topic, len(lines)))
        self.assertFalse(self.rosout.lines('go_nowhere', node='/print_info'),
                         'print_info echoes only commands that are accepted')
        self.assertTrue(all(len(m.msg) <= 2000 for m in self.rosout.all))

    def test_2_a_huge_velocity_cannot_put_miro_off_its_grid(self):
        huge = Twist()
        huge.linear.x = huge.linear.y = 1.0e308
        end = rospy.get_time() + 3.0
        while rospy.get_time() < end:
            self.pubs['/cmd_vel'].publish(huge)
            clock().sleep(0.05)
        x, y, z, _ = self.odom.xyzyaw()
        self.assertTrue(all(math.isfinite(v) for v in (x, y, z)))
        self.assertTrue(-0.25 <= x <= 10.25 and -0.25 <= y <= 10.25, (x, y))
        count = self.arrivals.count
        self.assertTrue(wait_until(lambda: self.arrivals.count > count, 60.0),
                        'MiRo arrives somewhere again')
        a = self.arrivals.msg.data
        self.assertLessEqual(math.hypot(a[2] - a[0], a[3] - a[1]), 0.05)

    def test_3_a_controller_killed_mid_move_drives_on(self):
        targets = Watch('/target_pos', Int64MultiArray)
        pause = rospy.ServiceProxy('/gazebo/pause_physics', Empty)
        unpause = rospy.ServiceProxy('/gazebo/unpause_physics', Empty)

        def arrived_at(target, since):
            return [a for a in self.arrivals.all[since:] if tuple(a.data[:2]) == target]
        for _ in range(5):          # a target MiRo has not reached yet, the world paused
            count, since = targets.count, self.arrivals.count
            self.assertTrue(wait_until(lambda: targets.count > count, 60.0), 'no new target')
            pause()        # the respawn takes wall time: no order times out meanwhile
            time.sleep(0.5)    # (wall) what is on its way lands: an arrival, a newer target
            target = tuple(targets.msg.data)     # the one the grounding sends again
            if not arrived_at(target, since):
                break
            unpause()
        numbers = [a.data[4] for a in self.arrivals.all]
        last = rospy.get_param('/all', [])      # the controller's own count
        last = int(last[4]) if len(last) == 5 else 0
        late = len(self.rosout.lines('no arrival within'))
        try:
            old = kill_node('/robot_motion_controller')
            deadline = time.monotonic() + 30.0
            while node_pid('/robot_motion_controller') in (None, old):
                self.assertLess(time.monotonic(), deadline, 'the controller did not come back')
                time.sleep(0.1)
            time.sleep(2.0)      # its subscriptions connect (wall time: the world is paused)
        finally:
            unpause()
        self.assertTrue(wait_until(lambda: arrived_at(target, len(numbers)), 60.0),
                        'no arrival at %s after the controller came back' % (target,))
        arrival = arrived_at(target, len(numbers))[0]
        self.assertEqual(arrival.data[4], last + 1)
        # on its own: not an order sent again after the state manager gave up waiting
        self.assertEqual(self.rosout.lines('no arrival within')[late:], [])

    def test_4_a_refused_target_is_not_announced(self):
        pub = rospy.Publisher('/target_pos', Int64MultiArray, queue_size=10)
        wait_for_every_subscriber(pub)       # the controller, print_info, the state manager...
        for data in ([1, 2, 3], [100, -100], []):
            pub.publish(Int64MultiArray(data=data))
        self.assertTrue(eventually(lambda: self.rosout.lines(
            'is not a grid point', node='/robot_motion_controller'), 10.0, 10.0),
            'the controller refused nothing')
        pub.publish(Int64MultiArray(data=[2, 9]))       # and a good one is announced
        self.assertTrue(eventually(lambda: self.rosout.lines('target: (2, 9)',
                                                             node='/print_info'), 10.0, 10.0))
        said = [m.msg for m in self.rosout.lines('target: (', node='/print_info')]
        for shown in ('target: (1, 2)', 'target: (100, -100)', 'target: ()'):
            self.assertNotIn(shown, said)


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_miro_robustness', TestMiroRobustness)

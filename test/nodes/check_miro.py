#!/usr/bin/env python3
"""Scenario B driven only by /voice and /gesture, as a person at a shell
would (no simulated person). The steps run in order on one system:
a word said asleep is not acted on after waking; a call mid-wander starts
PLAY within 1 s; with no gesture ever PLAY goes to (5, 5); an order said on
the way is obeyed; with silence MiRo follows the pointed place."""
import math
import unittest

import rospy
import rostest
from std_msgs.msg import Float64MultiArray, Int64MultiArray, String
from std_srvs.srv import Empty
from visualization_msgs.msg import MarkerArray

from checks import Pose, Rosout, Watch, clock, wait_for_subscribers, wait_until
from exp_assignment2.msg import Gesture

TOLERANCE = 0.05


class TestMiro(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_miro')
        clock()
        cls.states = Watch('/state', String, keep=True)
        cls.commands = Watch('/command', String, keep=True)
        cls.arrivals = Watch('/arrival', Float64MultiArray, keep=True)
        cls.targets = Watch('/target_pos', Int64MultiArray, keep=True)
        cls.odom = Pose('/odom')
        cls.rosout = Rosout()
        cls.voice = rospy.Publisher('/voice', String, queue_size=10)
        cls.gesture = rospy.Publisher('/gesture', Gesture, queue_size=10)
        # the world starts paused: nothing happens before we listen
        rospy.wait_for_service('/gazebo/unpause_physics', timeout=30)
        rospy.ServiceProxy('/gazebo/unpause_physics', Empty)()
        wait_for_subscribers(cls.voice)
        wait_for_subscribers(cls.gesture)

    def state(self):
        return self.states.msg.data if self.states.msg else None

    def say(self, text):
        rospy.loginfo('the person says %r', text)
        self.voice.publish(String(text))

    def arrived_at(self, x, y, after=0):
        """Arrivals at (x, y) after the first ``after`` ones, within the tolerance."""
        return [a.data for a in self.arrivals.all[after:] if tuple(a.data[:2]) == (x, y)
                and math.hypot(a.data[2] - x, a.data[3] - y) <= TOLERANCE]

    def test_1_a_call_said_while_asleep_is_not_acted_on_after_waking(self):
        self.assertTrue(wait_until(lambda: self.state() == 'SLEEP STATE', 10.0))
        self.say('play')
        self.assertTrue(wait_until(lambda: self.rosout.lines('does not listen'), 5.0))
        self.assertTrue(wait_until(lambda: self.state() == 'NORMAL', 30.0))
        woke = rospy.get_time()
        # exactly 5 s of ROS time (wait_until would stretch it on a loaded machine)
        self.assertFalse(clock().wait_until(lambda: self.state() == 'PLAY STATE', 5.0),
                         'PLAY %.1f s after waking' % (rospy.get_time() - woke))

    def test_2_a_call_mid_wander_starts_play_within_1s(self):
        seen = len(self.targets.all)

        def long_wander():
            """A random point at least 2 m from MiRo (it may draw its own)."""
            x, y, _, _ = self.odom.xyzyaw()
            return [t.data for t in self.targets.all[seen:] if t.layout.dim
                    and t.layout.dim[0].label == 'go_rand'
                    and math.hypot(t.data[0] - x, t.data[1] - y) >= 2.0]
        self.assertTrue(wait_until(long_wander, 60.0), 'no wander of 2 m or more')
        arrivals = self.arrivals.count
        clock().sleep(0.5)                                     # on its way
        self.assertEqual(self.arrivals.count, arrivals, 'the wander was too short')
        self.say('hey buddy')
        self.assertTrue(wait_until(lambda: self.state() == 'PLAY STATE', 10.0),
                        'state %r' % self.state())
        # within 1 s of simulated time, by the state manager's own stamps
        def stamps():
            heard = self.rosout.lines("the person says 'hey buddy'", node='/state_manager')
            left = self.rosout.lines('called while wandering', node='/state_manager')
            return heard and left and (heard[-1].header.stamp.to_sec(),
                                       left[-1].header.stamp.to_sec())
        self.assertTrue(wait_until(stamps, 10.0),
                        'lines: %s' % [m.msg for m in self.rosout.all[-10:]])
        heard, left = stamps()
        took = left - heard
        rospy.loginfo('PLAY %.2f s of simulated time after the call', took)
        self.assertTrue(0.0 <= took <= 1.0, took)

    def test_3_with_no_gesture_ever_play_goes_to_5_5_and_an_order_on_the_way_is_obeyed(self):
        self.assertTrue(wait_until(lambda: self.commands.msg.data == 'go to 5 5', 5.0))
        before = len(self.arrivals.all)
        clock().sleep(0.5)
        self.say('go to 6 2')                                  # while going to (5, 5)
        # for the next round (test 4): PLAY's first round has already looked
        self.gesture.publish(Gesture(person_x=4, person_y=4, point_x=8, point_y=2))
        self.assertTrue(wait_until(lambda: self.arrived_at(5, 5, before), 30.0))
        self.assertTrue(wait_until(lambda: self.arrived_at(6, 2, before), 30.0),
                        'arrivals: %s' % [a.data for a in self.arrivals.all[before:]])

    def test_4_with_silence_miro_goes_where_the_person_points(self):
        before, states = len(self.arrivals.all), len(self.states.all)
        self.assertTrue(wait_until(lambda: self.arrived_at(4, 4, before), 30.0))
        self.assertTrue(wait_until(lambda: self.arrived_at(8, 2, before), 30.0),
                        'arrivals: %s' % [a.data for a in self.arrivals.all[before:]])
        self.assertTrue(wait_until(lambda: 'NORMAL' in [m.data for m in self.states.all[states:]],
                                   20.0))

    def test_5_rviz_shows_the_grid_home_and_the_person_where_the_gesture_put_them(self):
        markers = Watch('/gazebo/world_markers', MarkerArray)
        self.assertTrue(wait_until(lambda: markers.msg is not None, 10.0))

        def person_at(x, y):
            return [m for m in markers.msg.markers if m.ns == 'person'
                    and abs(m.pose.position.x - x) < 0.3 and abs(m.pose.position.y - y) < 0.3]
        self.assertTrue(wait_until(lambda: person_at(4, 4), 10.0),
                        'the gesture of test 4 put the person at (4, 4)')
        spaces = {m.ns for m in markers.msg.markers}
        self.assertTrue({'home', 'person', 'grid'} <= spaces, spaces)
        home = [m for m in markers.msg.markers if m.ns == 'home'][0]
        self.assertEqual((home.pose.position.x, home.pose.position.y), (3.0, 3.0))
        grid = [m for m in markers.msg.markers if m.ns == 'grid'][0]
        xs = sorted({round(p.x, 3) for p in grid.points})
        self.assertEqual(xs, [float(x) for x in range(11)])


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'check_miro', TestMiro)

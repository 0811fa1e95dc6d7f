"""The person MiRo plays with: what they say and where they point.

:class:`Person` merges two sources. What arrives on ``/voice``
(std_msgs/String) and ``/gesture`` (exp_assignment2/Gesture) always takes
precedence; with simulation on (``~simulate_person``, default true) a seeded
generator stands in when nobody spoke, as the original's random user did.
"""
import random
import threading

import rospy
from std_msgs.msg import String

from exp_assignment2.commands import parse_or_report, parse_voice
from exp_assignment2.msg import Gesture
from exp_assignment2.world import GRID_MAX, GRID_MIN, on_grid


class SimulatedPerson(object):
    """Random words and gestures from a seeded generator (no ROS)."""

    def __init__(self, seed=0, call_probability=0.3):
        self.rng = random.Random(seed)
        self.call_probability = call_probability

    def point(self):
        return self.rng.randint(GRID_MIN, GRID_MAX), self.rng.randint(GRID_MIN, GRID_MAX)

    def says(self, playing):
        """Text the person says, or '' for silence."""
        if not playing:
            if self.rng.random() < self.call_probability:
                return self.rng.choice(['play', 'hey buddy'])
            return ''
        choice = self.rng.randrange(3)
        if choice == 0:
            return 'go to %d %d' % self.point()
        if choice == 1:
            return self.rng.choice(['play', 'hey buddy'])
        return ''

    def gesture(self):
        """((person_x, person_y), (point_x, point_y))."""
        return self.point(), self.point()


class Person(object):
    """What the person says and does, topics first, simulation second."""

    def __init__(self, simulate=True, seed=0):
        self.sim = SimulatedPerson(seed) if simulate else None
        self.lock = threading.Condition()
        self.heard = []            # parsed voice commands not yet used
        self.gesture = None        # ((px, py), (gx, gy)) last valid gesture
        rospy.Subscriber('/voice', String, self._on_voice, queue_size=10)
        rospy.Subscriber('/gesture', Gesture, self._on_gesture, queue_size=10)

    def _on_voice(self, msg):
        cmd = parse_or_report(parse_voice, msg.data, lambda why: rospy.logerr('/voice: %s', why))
        if cmd is None:
            return
        rospy.loginfo('/voice: the person says %r', msg.data.strip())
        with self.lock:
            self.heard.append(cmd)
            self.lock.notify_all()

    def _on_gesture(self, msg):
        if not (on_grid(msg.person_x, msg.person_y) and on_grid(msg.point_x, msg.point_y)):
            rospy.logerr('/gesture: person (%d, %d) pointing at (%d, %d) is off the grid '
                         '[%d, %d]; ignored', msg.person_x, msg.person_y, msg.point_x,
                         msg.point_y, GRID_MIN, GRID_MAX)
            return
        rospy.loginfo('/gesture: person at (%d, %d) points at (%d, %d)', msg.person_x,
                      msg.person_y, msg.point_x, msg.point_y)
        with self.lock:
            self.gesture = ((msg.person_x, msg.person_y), (msg.point_x, msg.point_y))
            self.lock.notify_all()

    def clear(self):
        """Forget what was said before now."""
        with self.lock:
            self.heard = []

    def listen(self, playing, seconds):
        """What the person says within ``seconds`` (wall-bounded by ROS time).

        Returns a :class:`~exp_assignment2.commands.VoiceCommand` or None.
        """
        end = rospy.Time.now() + rospy.Duration(seconds)
        while not rospy.is_shutdown():
            with self.lock:
                if self.heard:
                    return self.heard.pop(0)
            if rospy.Time.now() >= end:
                break
            rospy.sleep(0.05)
        if self.sim is not None:
            text = self.sim.says(playing)
            if text:
                rospy.loginfo('simulated person says %r', text)
                return parse_voice(text)
        return None

    def where(self):
        """((person_x, person_y), (point_x, point_y)), or None if unknown."""
        with self.lock:
            if self.gesture is not None:
                return self.gesture
        if self.sim is not None:
            gesture = self.sim.gesture()
            rospy.loginfo('simulated person at %s points at %s', *gesture)
            return gesture
        return None

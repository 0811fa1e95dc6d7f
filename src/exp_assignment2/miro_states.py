"""Scenario B's behaviour: MiRo's SMACH states SLEEP (initial), NORMAL, PLAY.

The manager publishes ``/command`` (``go_home``, ``go_rand``, ``go to X Y``)
and waits, in ROS time with a timeout, for the motion controller's arrival
event on ``/arrival``: no parameter is polled.
"""
import random
import threading

import rospy
from std_msgs.msg import Float64MultiArray, Int64MultiArray, String

from exp_assignment2.commands import format_go_to
from exp_assignment2.smach_api import smach

# SMACH label -> the original's /state parameter value
STATE_PARAM = {'SLEEP': 'SLEEP STATE', 'NORMAL': 'NORMAL', 'PLAY': 'PLAY STATE'}


class MiroParams(object):
    """The behaviour's numbers from ``~`` parameters."""

    DEFAULTS = dict(loops=3, sleep_probability=0.2, sleep_time=4.0, listen_time=3.0,
                    arrival_timeout=60.0, wait_time=2.0)

    def __init__(self, get=rospy.get_param):
        for key, default in self.DEFAULTS.items():
            setattr(self, key, type(default)(get('~' + key, default)))


class Miro(object):
    """Command out, acknowledgement and arrival in; shared by the states."""

    ACK_TIMEOUT = 1.0   # wall s for the grounding node to answer an order

    def __init__(self, person, params, seed=0):
        self.person, self.p = person, params
        self.rng = random.Random(seed)
        self.arrivals = 0
        self.targets = 0
        self.cond = threading.Condition()
        self.cmd_pub = rospy.Publisher('/command', String, queue_size=10)
        rospy.Subscriber('/arrival', Float64MultiArray, self._on_arrival, queue_size=10)
        rospy.Subscriber('/target_pos', Int64MultiArray, self._on_target, queue_size=10)

    def _on_arrival(self, msg):
        with self.cond:
            self.arrivals += 1
            self.cond.notify_all()

    def _on_target(self, msg):
        with self.cond:
            self.targets += 1
            self.cond.notify_all()

    def _send(self, command):
        """Publish until the grounding node answers on /target_pos: an order
        sent before it is connected (at start-up) would otherwise be lost."""
        while not rospy.is_shutdown():
            with self.cond:
                before = self.targets
            self.cmd_pub.publish(String(command))
            with self.cond:
                if self.cond.wait_for(lambda: self.targets > before, self.ACK_TIMEOUT):
                    return True
            rospy.logwarn_throttle(10, '%r: no answer on /target_pos yet, sending again'
                                   % command)
        return False

    def go(self, command):
        """Order ``command`` and wait (ROS time) for the arrival; True if it came."""
        with self.cond:
            before = self.arrivals
        rospy.set_param('/arrived', 0)
        if not self._send(command):
            return False
        end = rospy.Time.now() + rospy.Duration(self.p.arrival_timeout)
        while not rospy.is_shutdown() and rospy.Time.now() < end:
            with self.cond:
                if self.cond.wait_for(lambda: self.arrivals > before, 0.05):
                    return True
        rospy.logwarn('%r: no arrival within %.0f s', command, self.p.arrival_timeout)
        return False


class MiroSleep(smach.State):
    """Go home, rest, then NORMAL."""

    def __init__(self, miro):
        smach.State.__init__(self, outcomes=['wake', 'shutdown'])
        self.miro = miro

    def execute(self, ud):
        self.miro.go('go_home')
        rospy.sleep(self.miro.p.sleep_time)
        return 'shutdown' if rospy.is_shutdown() else 'wake'


class MiroNormal(smach.State):
    """Listen for a call word (-> PLAY); else wander; by chance or after
    ``loops`` wanders -> SLEEP."""

    def __init__(self, miro):
        smach.State.__init__(self, outcomes=['play', 'sleep', 'shutdown'])
        self.miro = miro

    def execute(self, ud):
        miro, p = self.miro, self.miro.p
        miro.person.clear()
        for _ in range(p.loops):
            heard = miro.person.listen(playing=False, seconds=p.listen_time)
            if rospy.is_shutdown():
                return 'shutdown'
            if heard is not None and heard.kind == 'play':
                return 'play'
            if heard is not None:
                rospy.loginfo('NORMAL: %r only counts in PLAY', format_go_to(heard.x, heard.y))
            miro.go('go_rand')
            if miro.rng.random() < p.sleep_probability:
                return 'sleep'
        return 'sleep'


class MiroPlay(smach.State):
    """Go to the person, then obey their 'go to X Y' or their pointing;
    ``loops`` times, then NORMAL."""

    def __init__(self, miro):
        smach.State.__init__(self, outcomes=['normal', 'shutdown'])
        self.miro = miro

    def execute(self, ud):
        miro, p = self.miro, self.miro.p
        for _ in range(p.loops):
            where = miro.person.where()
            if where is None:
                rospy.logwarn('PLAY: nobody to play with (no /gesture yet)')
                return 'normal'
            (px, py), (gx, gy) = where
            miro.go(format_go_to(px, py))
            heard = miro.person.listen(playing=True, seconds=p.listen_time)
            if rospy.is_shutdown():
                return 'shutdown'
            if heard is not None and heard.kind == 'go_to':
                miro.go(format_go_to(heard.x, heard.y))
            elif heard is not None:          # 'play' again: just wait
                rospy.sleep(p.wait_time)
            else:                            # silence: follow the pointing
                miro.go(format_go_to(gx, gy))
        return 'normal'


def build_state_machine(miro):
    sm = smach.StateMachine(outcomes=['shutdown'])
    with sm:
        smach.StateMachine.add('SLEEP', MiroSleep(miro), transitions={'wake': 'NORMAL'})
        smach.StateMachine.add('NORMAL', MiroNormal(miro),
                               transitions={'play': 'PLAY', 'sleep': 'SLEEP'})
        smach.StateMachine.add('PLAY', MiroPlay(miro), transitions={'normal': 'NORMAL'})
    return sm

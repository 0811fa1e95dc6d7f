"""Scenario A's behaviour: SMACH states NORMAL, SLEEP and PLAY.

Every duration is ROS time (the simulator's clock) and every number a
parameter of the ``state_machine`` node (see :class:`DogParams`). States run a
control loop at ``~control_rate``; the ball servo itself runs in the camera
callback (:class:`~exp_assignment2.dog_io.BallWatcher`).
"""
import math
import random

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import Twist
from std_msgs.msg import Float64

from exp_assignment2.ball_motion import ball_goal
from exp_assignment2.dog_io import BallFollower
from exp_assignment2.msg import PlanningAction
from exp_assignment2.smach_api import smach
from exp_assignment2.world import ARENA_GOAL_LIMIT, DOG_HOME

TERMINAL = (GoalStatus.SUCCEEDED, GoalStatus.ABORTED, GoalStatus.PREEMPTED,
            GoalStatus.REJECTED, GoalStatus.RECALLED, GoalStatus.LOST)


class DogParams(object):
    """The behaviour's numbers, from ``~`` parameters with the defaults below."""

    DEFAULTS = dict(
        control_rate=20.0,          # Hz of ROS time
        sleep_probability=0.2,      # NORMAL: chance of going to sleep each round
        look_around_time=6.0,       # NORMAL: s turning in place before wandering
        look_rate=0.5,              # rad/s while looking around / searching
        wander_timeout=60.0,        # s for one random goal
        home_timeout=120.0,         # s to reach the kennel
        sleep_time=14.0,            # s asleep at home
        lost_timeout=None,          # PLAY: s without the ball; default one full turn
        rest_speed=0.05,            # PLAY: |v|, |w| below this is "at rest"
        rest_time=1.0,              # PLAY: s at rest before the head sweep
        head_angle=math.radians(45),
        head_hold=2.0,              # s holding each head position
    )

    def __init__(self, get=rospy.get_param):
        for key, default in self.DEFAULTS.items():
            value = get('~' + key, default)
            setattr(self, key, None if value is None else float(value))
        if self.lost_timeout is None:
            self.lost_timeout = 2.0 * math.pi / self.look_rate


class Dog(object):
    """What the states share: camera, publishers, the robot's action client."""

    def __init__(self, watcher, params, seed):
        self.watcher = watcher
        self.p = params
        self.rng = random.Random(seed)
        self.cmd_pub = rospy.Publisher('/robot/cmd_vel', Twist, queue_size=1)
        self.head_pub = rospy.Publisher('/robot/joint_position_controller/command', Float64,
                                        queue_size=1, latch=True)
        self.robot = actionlib.SimpleActionClient('/robot_reaching_goal', PlanningAction)
        if not self.robot.wait_for_server(rospy.Duration(60)):
            raise RuntimeError('no /robot_reaching_goal action server after 60 s')
        self.follower = BallFollower(self.cmd_pub, search_rate=params.look_rate)

    def rate(self):
        return rospy.Rate(self.p.control_rate)

    def turn(self, angular):
        twist = Twist()
        twist.angular.z = angular
        self.cmd_pub.publish(twist)

    def stop(self):
        self.cmd_pub.publish(Twist())

    def head(self, angle):
        self.head_pub.publish(Float64(angle))

    def go_to(self, x, y, timeout, watch_from=None):
        """Drive to (x, y) through the action; 'ball' if seen (goal cancelled),
        else 'done', 'failed' or 'shutdown'."""
        self.robot.send_goal(ball_goal(x, y))
        deadline = rospy.Time.now() + rospy.Duration(timeout)
        rate = self.rate()
        while not rospy.is_shutdown():
            if watch_from is not None and self.watcher.seen_since(watch_from):
                self.robot.cancel_goal()
                self.stop()
                return 'ball'
            state = self.robot.get_state()
            if state in TERMINAL:
                return 'done' if state == GoalStatus.SUCCEEDED else 'failed'
            if rospy.Time.now() > deadline:
                self.robot.cancel_goal()
                return 'failed'
            rate.sleep()
        self.robot.cancel_goal()
        return 'shutdown'


class Normal(smach.State):
    """Sleep by chance, else search: look around, then wander; ball -> PLAY."""

    def __init__(self, dog):
        smach.State.__init__(self, outcomes=['sleep', 'play', 'shutdown'])
        self.dog = dog

    def execute(self, ud):
        dog, p = self.dog, self.dog.p
        since = rospy.Time.now()
        while not rospy.is_shutdown():
            if dog.rng.random() < p.sleep_probability:
                return 'sleep'
            if self.look_around(since):
                return 'play'
            x = dog.rng.uniform(-ARENA_GOAL_LIMIT, ARENA_GOAL_LIMIT)
            y = dog.rng.uniform(-ARENA_GOAL_LIMIT, ARENA_GOAL_LIMIT)
            rospy.loginfo('NORMAL: nothing seen, wandering to (%.1f, %.1f)', x, y)
            outcome = dog.go_to(x, y, p.wander_timeout, watch_from=since)
            if outcome == 'ball':
                rospy.loginfo('NORMAL: ball seen, robot goal preempted')
                return 'play'
        return 'shutdown'

    def look_around(self, since):
        """Turn in place for look_around_time; True as soon as the ball is seen."""
        dog = self.dog
        end = rospy.Time.now() + rospy.Duration(dog.p.look_around_time)
        rate = dog.rate()
        while not rospy.is_shutdown() and rospy.Time.now() < end:
            if dog.watcher.seen_since(since):
                dog.stop()
                return True
            dog.turn(dog.p.look_rate)
            rate.sleep()
        dog.stop()
        return dog.watcher.seen_since(since)


class Sleep(smach.State):
    """Go home, rest, wake up; the ball is ignored."""

    def __init__(self, dog):
        smach.State.__init__(self, outcomes=['wake', 'shutdown'])
        self.dog = dog

    def execute(self, ud):
        dog = self.dog
        outcome = dog.go_to(DOG_HOME[0], DOG_HOME[1], dog.p.home_timeout)
        if outcome == 'shutdown':
            return 'shutdown'
        if outcome != 'done':
            rospy.logwarn('SLEEP: could not reach home (%s); sleeping here', outcome)
        dog.stop()
        rospy.sleep(dog.p.sleep_time)
        return 'shutdown' if rospy.is_shutdown() else 'wake'


class Play(smach.State):
    """Follow the ball; at rest near it sweep the head; lost -> NORMAL."""

    def __init__(self, dog):
        smach.State.__init__(self, outcomes=['lost', 'shutdown'])
        self.dog = dog

    def execute(self, ud):
        dog, p = self.dog, self.dog.p
        last_seen = rospy.Time.now()
        rest_since = None
        rate = dog.rate()
        dog.watcher.attach(dog.follower)
        try:
            while not rospy.is_shutdown():
                now = rospy.Time.now()
                seen = dog.watcher.last_seen()
                if seen is not None and seen > last_seen:
                    last_seen = seen
                if (now - last_seen).to_sec() > p.lost_timeout:
                    rospy.loginfo('PLAY: ball lost for %.1f s', p.lost_timeout)
                    return 'lost'
                cmd = dog.follower.last_cmd
                resting = (dog.watcher.seen_within(now, 0.5)
                           and abs(cmd.linear.x) < p.rest_speed
                           and abs(cmd.angular.z) < p.rest_speed)
                rest_since = (rest_since or now) if resting else None
                if rest_since is not None and (now - rest_since).to_sec() >= p.rest_time:
                    if not self.sweep_head():
                        return 'shutdown'
                    rest_since = None
                rate.sleep()
            return 'shutdown'
        finally:
            dog.watcher.attach(None)
            dog.stop()
            dog.head(0.0)

    def sweep_head(self):
        """Head to +angle, hold, -angle, hold, back to 0 (servo paused)."""
        dog, p = self.dog, self.dog.p
        rospy.loginfo('PLAY: at the ball, moving the head')
        dog.watcher.attach(None)
        dog.stop()
        for angle in (p.head_angle, -p.head_angle, 0.0):
            dog.head(angle)
            rospy.sleep(p.head_hold)
            if rospy.is_shutdown():
                return False
        dog.watcher.attach(dog.follower)
        return True


def build_state_machine(dog):
    """NORMAL (initial) <-> SLEEP, NORMAL -> PLAY -> NORMAL."""
    sm = smach.StateMachine(outcomes=['shutdown'])
    with sm:
        smach.StateMachine.add('NORMAL', Normal(dog),
                               transitions={'sleep': 'SLEEP', 'play': 'PLAY'})
        smach.StateMachine.add('SLEEP', Sleep(dog), transitions={'wake': 'NORMAL'})
        smach.StateMachine.add('PLAY', Play(dog), transitions={'lost': 'NORMAL'})
    return sm

"""``geometry_grounding``: ``/command`` (``go_home``, ``go_rand``, ``go to X
Y``) becomes a grid point on ``/target_pos``, labelled with the command.

The target not yet reached (no ``/arrival`` at it) goes again to a node that
subscribes to ``/target_pos`` later: a motion controller respawned in the
middle of a move picks it up and drives on.

Parameters: ``~seed``; the original's ``/home_posx``, ``/home_posy``.
"""
import random
import threading

import rospy
from std_msgs.msg import (Float64MultiArray, Int64MultiArray, MultiArrayDimension,
                          MultiArrayLayout, String)

from exp_assignment2 import grid
from exp_assignment2.grammar import CommandError
from exp_assignment2.grounding import ground
from exp_assignment2.ros.log import refusal_log


def main():
    rospy.init_node('geometry_grounding')
    rng = random.Random(rospy.get_param('~seed', 0))
    outstanding = OutstandingTarget()
    pub = rospy.Publisher('/target_pos', Int64MultiArray, queue_size=10,
                          subscriber_listener=outstanding)
    refuse = refusal_log('/command')

    def on_command(msg):
        home = (rospy.get_param('/home_posx', grid.HOME[0]),
                rospy.get_param('/home_posy', grid.HOME[1]))
        try:
            x, y = ground(msg.data, home, rng)
        except CommandError as exc:
            refuse(str(exc))
            return
        layout = MultiArrayLayout(dim=[MultiArrayDimension(label=msg.data, size=2, stride=2)])
        target = Int64MultiArray(layout=layout, data=[x, y])
        outstanding.set(target)
        pub.publish(target)
    rospy.Subscriber('/command', String, on_command, queue_size=100)
    rospy.Subscriber('/arrival', Float64MultiArray, outstanding.on_arrival, queue_size=10)
    rospy.spin()


class OutstandingTarget(rospy.SubscribeListener):
    """The last target until an ``/arrival`` at it; sent to each new subscriber."""

    def __init__(self):
        rospy.SubscribeListener.__init__(self)
        self.lock, self.target = threading.Lock(), None

    def set(self, target):
        with self.lock:
            self.target = target

    def on_arrival(self, msg):
        with self.lock:
            if self.target is not None and list(msg.data[:2]) == list(self.target.data):
                self.target = None

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        with self.lock:
            target = self.target
        if target is not None:
            peer_publish(target)

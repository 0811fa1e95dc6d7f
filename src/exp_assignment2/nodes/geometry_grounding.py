"""``geometry_grounding``: ``/command`` (``go_home``, ``go_rand``, ``go to X
Y``) becomes a grid point on ``/target_pos``, labelled with the command.

Parameters: ``~seed``; the original's ``/home_posx``, ``/home_posy``.
"""
import random

import rospy
from std_msgs.msg import Int64MultiArray, MultiArrayDimension, MultiArrayLayout, String

from exp_assignment2 import grid
from exp_assignment2.grammar import CommandError
from exp_assignment2.grounding import ground
from exp_assignment2.ros.log import refusal_log


def main():
    rospy.init_node('geometry_grounding')
    rng = random.Random(rospy.get_param('~seed', 0))
    pub = rospy.Publisher('/target_pos', Int64MultiArray, queue_size=10)
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
        pub.publish(Int64MultiArray(layout=layout, data=[x, y]))
    rospy.Subscriber('/command', String, on_command, queue_size=100)
    rospy.spin()

"""``print_info``: logs MiRo's state changes, commands, targets and arrivals.

Only commands the grounding node accepts, and targets the motion controller
accepts, are echoed (they log the refusals, throttled), so a flood of bad
input does not flood this log either; what is echoed is quoted to 80
characters.
"""
import rospy
from std_msgs.msg import Float64MultiArray, Int64MultiArray, String

from exp_assignment2 import grid
from exp_assignment2.behaviour.miro import STATE_PARAM
from exp_assignment2.grammar import CommandError, parse_motion_command, quote
from exp_assignment2.ros.clock import RosClock


def on_command(msg):
    try:
        parse_motion_command(msg.data)
    except CommandError:
        return
    rospy.loginfo('command: %s', quote(msg.data.strip()))


def on_target(msg):
    target = grid.target_point(msg.data)
    if target is not None:
        rospy.loginfo('target: (%d, %d)', *target)


def on_state(msg):
    known = msg.data in STATE_PARAM.values()
    rospy.loginfo('state: %s', msg.data if known else quote(msg.data))


def on_arrival(msg):
    if len(msg.data) >= 5:
        rospy.loginfo('arrival #%d: target (%g, %g), robot at (%.2f, %.2f)', int(msg.data[4]),
                      *msg.data[:4])


def main():
    rospy.init_node('print_info')
    clock = RosClock()

    def in_ros_time(log):
        """``log(msg)`` once ROS time runs: the latched /state reaches a respawned
        print_info before /clock does, and its line would carry 0.000000."""
        def callback(msg):
            if clock.wait_for_time():
                log(msg)
        return callback
    rospy.Subscriber('/state', String, in_ros_time(on_state), queue_size=100)
    rospy.Subscriber('/command', String, in_ros_time(on_command), queue_size=100)
    rospy.Subscriber('/target_pos', Int64MultiArray, in_ros_time(on_target), queue_size=100)
    rospy.Subscriber('/arrival', Float64MultiArray, in_ros_time(on_arrival), queue_size=100)
    rospy.spin()

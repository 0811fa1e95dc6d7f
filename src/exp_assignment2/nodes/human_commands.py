"""``human_commands``: a person moves the ball from the shell with
``/ball/command`` (std_msgs/String): ``go to X Y``, ``hide``, ``show``,
``auto``, ``stop``. Refusals are logged (throttled, input quoted to 80
characters); any accepted command but ``auto`` pauses ``move_ball_around``
through ``/ball/auto``.
"""
import rospy
from nav_msgs.msg import Odometry
from std_msgs.msg import Bool, String

from exp_assignment2.behaviour.ball import BallCommands
from exp_assignment2.nodes.move_ball_around import AUTO_TOPIC
from exp_assignment2.ros.actions import start_client
from exp_assignment2.ros.log import RosLog, refusal_log


def main():
    _, ball = start_client('human_commands', '/reaching_goal')
    if ball is None:
        return
    auto_pub = rospy.Publisher(AUTO_TOPIC, Bool, queue_size=1, latch=True)
    where = {}
    rospy.Subscriber('/ball/odom', Odometry, lambda msg: where.update(
        xy=(msg.pose.pose.position.x, msg.pose.pose.position.y)), queue_size=1)
    commands = BallCommands(ball, lambda flag: auto_pub.publish(Bool(flag)),
                            lambda: where.get('xy'), refusal_log('/ball/command'), RosLog())
    rospy.Subscriber('/ball/command', String, lambda msg: commands.handle(msg.data),
                     queue_size=100)
    rospy.spin()

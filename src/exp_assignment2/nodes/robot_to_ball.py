"""``robot_to_ball``: the original's stand-alone ball follower: the visual
servo on every camera frame, turning in place while the ball is not seen.

Parameters: ``~target_radius_ratio``, ``~max_linear``, ``~max_angular``,
``~search_rate``, ``~min_radius_at_800``, ``~gui``.
"""
import rospy

from exp_assignment2.control import BallFollower
from exp_assignment2.ros.clock import RosClock
from exp_assignment2.ros.dog import CommandPublisher, RosDogEyes
from exp_assignment2.ros.ending import run_until_shutdown
from exp_assignment2.ros.robot_model import turn_sign


def main():
    rospy.init_node('robot_to_ball')
    follower = BallFollower(float(rospy.get_param('~target_radius_ratio', 0.3)),
                            float(rospy.get_param('~max_linear', 0.8)),
                            float(rospy.get_param('~max_angular', 1.0)),
                            float(rospy.get_param('~search_rate', 0.5)))
    clock = RosClock()
    # the camera's first subscriber starts the world (simulator wait_for_camera)
    eyes = RosDogEyes(clock, float(rospy.get_param('~min_radius_at_800', 10.0)),
                      gui=bool(rospy.get_param('~gui', False)))
    if not clock.wait_for_time():
        return
    wheels = CommandPublisher(turn_sign())
    eyes.follow(lambda ball, width: wheels.drive(*follower.command(ball, width)))
    run_until_shutdown(rospy.spin)

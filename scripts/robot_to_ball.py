#!/usr/bin/env python3
"""Stand-alone ball follower (the original robot_to_ball)."""
import signal

# until rospy.init_node takes SIGINT over: roslaunch ending the launch while
# this node starts ends it quietly, not with a traceback from an import
signal.signal(signal.SIGINT, signal.SIG_DFL)

from exp_assignment2.nodes.robot_to_ball import main  # noqa: E402
from exp_assignment2.ros.ending import run_until_shutdown  # noqa: E402

run_until_shutdown(main)

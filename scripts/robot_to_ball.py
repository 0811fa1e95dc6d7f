#!/usr/bin/env python3
"""Stand-alone ball follower (the original robot_to_ball)."""
from exp_assignment2.nodes.robot_to_ball import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

#!/usr/bin/env python3
"""Stand-alone ball follower (the original robot_to_ball)."""
from exp_assignment2.nodes.robot_to_ball import main

main()

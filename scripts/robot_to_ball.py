#!/usr/bin/env python3
"""Stand-alone ball follower (the original robot_to_ball)."""
from exp_assignment2.dog_node import main_robot_to_ball

main_robot_to_ball()

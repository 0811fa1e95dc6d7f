#!/usr/bin/env python3
"""Drives the omnidirectional MiRo to /target_pos."""
from exp_assignment2.nodes.robot_motion_controller import main

main()

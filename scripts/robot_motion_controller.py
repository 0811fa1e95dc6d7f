#!/usr/bin/env python3
"""Drives the omnidirectional MiRo to /target_pos."""
from exp_assignment2.nodes.robot_motion_controller import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

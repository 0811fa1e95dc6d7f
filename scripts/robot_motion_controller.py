#!/usr/bin/env python3
"""Drives the omnidirectional MiRo to /target_pos."""
from exp_assignment2.miro_nodes import main_motion_controller

main_motion_controller()

#!/usr/bin/env python3
"""Turns /command into a grid point on /target_pos."""
from exp_assignment2.nodes.geometry_grounding import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

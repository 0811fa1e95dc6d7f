#!/usr/bin/env python3
"""The simulator node (node name gazebo) that stands in for Gazebo."""
from exp_assignment2.nodes.simulator import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

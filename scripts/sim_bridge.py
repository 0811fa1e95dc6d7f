#!/usr/bin/env python3
"""The pybullet simulator node that stands in for Gazebo."""
from exp_assignment2.sim_bridge_node import main

main()

#!/usr/bin/env python3
"""Draws a recorded run (rosbag) as a picture: rosrun exp_assignment2 plot_run.py BAG -o PNG."""
from exp_assignment2.nodes.plot_run import main

main()

#!/usr/bin/env python3
"""PlanningAction server /reaching_goal: moves the ball; the goal's z is its height."""
from exp_assignment2.nodes.go_to_point_ball import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

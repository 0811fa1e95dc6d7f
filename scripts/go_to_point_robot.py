#!/usr/bin/env python3
"""PlanningAction server /robot_reaching_goal: turn towards the goal, then drive."""
from exp_assignment2.nodes.go_to_point_robot import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

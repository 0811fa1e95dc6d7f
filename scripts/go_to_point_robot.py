#!/usr/bin/env python3
"""PlanningAction server /robot_reaching_goal: turn towards the goal, then drive."""
from exp_assignment2.planning_server import main_robot

main_robot()

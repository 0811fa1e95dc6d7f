#!/usr/bin/env python3
"""PlanningAction server /reaching_goal: moves (and hides) the ball."""
from exp_assignment2.planning_server import main_ball

main_ball()

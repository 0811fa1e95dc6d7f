#!/usr/bin/env python3
"""Moves the ball to random goals, waits, hides it, waits, again."""
from exp_assignment2.nodes.move_ball_around import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

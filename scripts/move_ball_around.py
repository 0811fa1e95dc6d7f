#!/usr/bin/env python3
"""Moves the ball to random goals, waits, hides it, waits, again."""
from exp_assignment2.ball_motion import main_auto

main_auto()

#!/usr/bin/env python3
"""Lets a person move the ball from the shell on /ball/command."""
from exp_assignment2.ball_motion import main_human

main_human()

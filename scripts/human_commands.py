#!/usr/bin/env python3
"""Lets a person move the ball from the shell on /ball/command."""
from exp_assignment2.nodes.human_commands import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

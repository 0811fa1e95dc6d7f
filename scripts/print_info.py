#!/usr/bin/env python3
"""Logs MiRo's state changes, commands, targets and arrivals."""
from exp_assignment2.nodes.print_info import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

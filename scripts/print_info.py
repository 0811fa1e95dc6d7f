#!/usr/bin/env python3
"""Logs MiRo's state changes, commands, targets and arrivals."""
from exp_assignment2.miro_nodes import main_print_info

main_print_info()

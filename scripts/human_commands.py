#!/usr/bin/env python3
"""Lets a person move the ball from the shell on /ball/command."""
from exp_assignment2.nodes.human_commands import main

main()

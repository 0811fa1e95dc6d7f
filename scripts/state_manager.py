#!/usr/bin/env python3
"""MiRo's behaviour: SLEEP, NORMAL and PLAY (SMACH), obeying voice and gestures."""
from exp_assignment2.nodes.state_manager import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

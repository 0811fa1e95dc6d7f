#!/usr/bin/env python3
"""MiRo's behaviour: SLEEP, NORMAL and PLAY (SMACH), obeying voice and gestures."""
from exp_assignment2.nodes.state_manager import main

main()

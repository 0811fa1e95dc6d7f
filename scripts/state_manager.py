#!/usr/bin/env python3
"""MiRo's behaviour: SLEEP, NORMAL and PLAY (SMACH), obeying voice and gestures."""
from exp_assignment2.miro_nodes import main_state_manager

main_state_manager()

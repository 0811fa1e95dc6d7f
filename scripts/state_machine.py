#!/usr/bin/env python3
"""The dog's behaviour: NORMAL, SLEEP and PLAY (SMACH)."""
from exp_assignment2.dog_node import main_state_machine

main_state_machine()

#!/usr/bin/env python3
"""The dog's behaviour: NORMAL, SLEEP and PLAY (SMACH)."""
from exp_assignment2.nodes.state_machine import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)

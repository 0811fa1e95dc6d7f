#!/usr/bin/env python3
"""Turns /command into a grid point on /target_pos."""
from exp_assignment2.miro_nodes import main_geometry_grounding

main_geometry_grounding()

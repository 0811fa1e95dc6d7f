"""Lets the unit tests import the library from src/ without a built workspace.

With the workspace sourced (tools/run does), ``exp_assignment2`` is catkin's
devel package, whose path covers both src/exp_assignment2 and the generated
messages; src/ is only added when that is not importable.
"""
import os
import sys

try:
    import exp_assignment2  # noqa: F401
except ImportError:
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))), 'src'))

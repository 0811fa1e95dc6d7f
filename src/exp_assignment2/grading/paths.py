"""Where the grader's own files are (no ROS): found here once, imported by
the rest. ``inside.py`` runs in the sandbox by path and finds ``src`` itself."""
import os

# src/exp_assignment2/grading/paths.py -> the repository (a workspace links to it)
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.realpath(__file__)))))
SIMULATOR = os.path.join(REPO, 'scripts', 'simulator.py')

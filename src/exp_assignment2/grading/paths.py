"""Where things are in this repository: found here once, imported by the rest.

No import of the package: ``run/inside.py`` runs in the sandbox as a script
and finds this file beside its own folder (the standard library only).
"""
import os

# src/exp_assignment2/grading/paths.py -> the repository (the workspace links to it)
GRADING = os.path.dirname(os.path.realpath(__file__))
SRC = os.path.dirname(os.path.dirname(GRADING))
REPO = os.path.dirname(SRC)
INSIDE = os.path.join(GRADING, 'run', 'inside.py')
SIMULATOR = os.path.join(REPO, 'scripts', 'simulator.py')
PROFILE_DIR = os.path.join(REPO, 'config', 'grading')
PACKAGE_XML = os.path.join(REPO, 'package.xml')

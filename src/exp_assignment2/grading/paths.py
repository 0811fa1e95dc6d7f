"""Where the grader's files are, found once (:mod:`exp_assignment2.layout`
decides between the source tree and an install space) and imported by the rest.

``ROOT`` holds everything of this package (a run's sandbox shows it
read-only); ``PACKAGE`` is the ROS package (its launch files, URDFs, the
profiles in config/grading); ``SRC`` the folder holding the Python package
(the repository's src/, or an install space's dist-packages).
"""
import os

from exp_assignment2.layout import LIBRARY as SRC, PACKAGE, ROOT, SCRIPTS, STAND_INS  # noqa: F401

GRADING = os.path.dirname(os.path.realpath(__file__))
INSIDE = os.path.join(GRADING, 'run', 'inside.py')
SIMULATOR = os.path.join(SCRIPTS, 'simulator.py')
PROFILE_DIR = os.path.join(PACKAGE, 'config', 'grading')
PACKAGE_XML = os.path.join(PACKAGE, 'package.xml')

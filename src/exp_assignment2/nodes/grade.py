"""``rosrun exp_assignment2 grade.py SUBMISSIONS ...``: the grader
(:mod:`exp_assignment2.grading.cli`; ``bash tools/run grade`` sets the
machine up first). Not a node: it starts none, and talks to no master."""
import sys

from exp_assignment2.grading.cli import main as grade_main


def main():
    sys.exit(grade_main())

#!/usr/bin/env python3
"""Gradescope's autograder: grades /autograder/submission into
/autograder/results/results.json (exp_assignment2.grading.gradescope;
docs/grading.md, "Gradescope"). --root DIR (or EXP2_AUTOGRADER_ROOT) for
another tree; arguments after -- go to grade (or EXP2_AUTOGRADER_ARGS)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'src'))
from exp_assignment2.grading.gradescope import main  # noqa: E402

sys.exit(main())

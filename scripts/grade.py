#!/usr/bin/env python3
"""Grade a folder of submissions (exp_assignment2.grading.cli; docs/grading.md)."""
import sys

from exp_assignment2.grading.cli import main

if __name__ == '__main__':
    sys.exit(main())

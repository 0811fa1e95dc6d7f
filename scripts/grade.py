#!/usr/bin/env python3
"""Grades a folder of submissions: rosrun exp_assignment2 grade.py SUBMISSIONS (docs/grading.md)."""
from exp_assignment2.nodes.grade import main

main()

#!/usr/bin/env python
"""A node written as much original student code is: its indentation mixes
tabs and spaces, which Python 2 read (a tab advances to the next multiple of
8 columns) and Python 3 refuses (TabError). Test fixture of the original-code
shell (test/unit/test_tab_rule*.py, test/test_original_env_tabs.py)."""
import sys

import tabs_helper


def count(n):
    total = 0
    for _ in range(n):
        total += 1
	total += 10
    return total


if __name__ == "__main__":
	print("count %d" % count(3))
        print("tally %d" % tabs_helper.tally(["a", "b"]))
	print("strings %r" % (tabs_helper.strings(),))
        print("argv %s" % " ".join(sys.argv[1:]))
	if "--fail" in sys.argv:
		tabs_helper.fail()

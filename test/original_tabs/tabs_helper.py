"""The module tabs_node.py imports, mixing tabs and spaces as well."""

SEPARATOR = "a	b"  # a tab inside a string literal stays a tab

BANNER = """first line
	second line, after a tab in the string
        third line, after eight spaces"""


def tally(words):
    seen = 0
    for _ in words:
        seen += 1
	seen += 100
    return seen


def strings():
	parts = [SEPARATOR,
		 BANNER]
        total = sum(len(part) for part in parts) + \
			0
	return parts[0], parts[1].split("\n")[1], total


def fail():
	raise ValueError("raised on line 27")

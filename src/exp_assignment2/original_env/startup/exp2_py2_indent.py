"""Python 2's tab rule, as plain text processing (no import machinery, no ROS).

Python 2 measured the indentation of a logical line in columns: a space
advances one column, a tab to the next multiple of 8, a form feed resets to 0.
Mixing tabs and spaces was therefore fine as long as the columns matched.
Python 3 measures the same columns but also with tabs as 1 column, and refuses
a file where the two disagree (TabError), which much original student code does.

``python2_indentation`` rewrites the indentation of every logical line that has
a tab in it as the same number of spaces, so Python 3 reads the block
structure Python 2 read. Like Python 2's tokenizer it only looks at the start
of a logical line: not inside a string (a tab in a string literal, one-line or
triple-quoted, stays a tab), not on a line continued by a backslash or inside
brackets, not on blank or comment-only lines. No line is added or removed, so
line numbers (tracebacks, error messages) stay those of the file.
"""

TAB_SIZE = 8  # Python 2's tokenizer: "Don't ever change this"
_INDENT_CHARS = ' \t\f'


def python2_column(indent):
    """The column Python 2's tokenizer reached after the whitespace ``indent``."""
    col = 0
    for char in indent:
        if char == ' ':
            col += 1
        elif char == '\t':
            col = (col // TAB_SIZE + 1) * TAB_SIZE
        else:  # form feed
            col = 0
    return col


def _scan(line, quote, depth):
    """Carry the tokenizer's state over one line: (open quote, bracket depth, continued)."""
    i, end = 0, len(line)
    continued = False
    while i < end:
        char = line[i]
        if quote:
            if char == '\\':  # escapes the next character, also in raw strings
                i += 2
            elif line.startswith(quote, i):
                i += len(quote)
                quote = None
            else:
                i += 1
            continue
        if char == '#':
            break
        if char in '([{':
            depth += 1
        elif char in ')]}':
            depth = max(depth - 1, 0)
        elif char in '\'"':
            quote = char * 3 if line.startswith(char * 3, i) else char
            i += len(quote)
            continue
        elif char == '\\' and i == end - 1:
            continued = True
        i += 1
    if quote and len(quote) == 1 and i <= end:
        # A one-line string left open without a backslash at the end: a syntax
        # error Python reports itself; the next line starts afresh.
        quote = None
    return quote, depth, continued


def python2_indentation(text):
    """Return ``(text, shifts)``: ``text`` with Python 2's tab rule applied.

    ``text`` is source code with '\\n' line ends. Each logical line whose
    indentation contains a tab gets that indentation as spaces, as many as
    Python 2 counted columns. ``shifts`` maps the number (from 1) of each line
    so changed to what to add to a column of the new line to find the same
    character in the old one.
    """
    lines = text.split('\n')  # not splitlines(): a form feed is not a line end
    shifts = {}
    quote, depth, continued = None, 0, False
    for index, line in enumerate(lines):
        if quote is None and depth == 0 and not continued:
            rest = line.lstrip(_INDENT_CHARS)
            indent = line[:len(line) - len(rest)]
            if '\t' in indent and rest and not rest.startswith('#'):
                column = python2_column(indent)
                line = ' ' * column + rest
                lines[index] = line
                shifts[index + 1] = len(indent) - column
        quote, depth, continued = _scan(line, quote, depth)
    return '\n'.join(lines), shifts


def has_tab_indentation(data):
    """Cheap test on source bytes: does some line start with whitespace holding a tab?"""
    if b'\t' not in data:
        return False
    return any(line.lstrip(b' \f').startswith(b'\t') for line in data.splitlines())


def python2_source(data):
    """``(source, shifts)``: bytes re-indented by Python 2's tab rule, or None.

    None if nothing changes. The encoding (PEP 263 cookie or BOM) is kept, so
    the result compiles as the file would; line ends become '\\n', one for
    one. ``shifts`` as ``python2_indentation`` gives them.
    """
    import io
    import tokenize
    try:
        encoding = tokenize.detect_encoding(io.BytesIO(data).readline)[0]
        text = data.decode(encoding)
    except (SyntaxError, UnicodeDecodeError, LookupError):
        return None  # Python reports a bad encoding itself
    text = text.replace('\r\n', '\n').replace('\r', '\n')
    fixed, shifts = python2_indentation(text)
    return (fixed.encode(encoding), shifts) if shifts else None

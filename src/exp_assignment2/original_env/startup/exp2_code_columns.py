"""Moves the column positions of a code object, for code compiled from re-indented source.

Since Python 3.11 a code object records, for each instruction, the columns of
the source it came from, and tracebacks underline that part of the line
(``^^^^``) in the text of the file. Code compiled from source re-indented by
Python 2's tab rule (a tab became up to eight spaces) has columns of the
re-indented line; ``shift_columns`` moves them by each line's change in
indentation, so they point into the line as it is in the file. Line numbers
are not touched (they never moved). Before 3.11 there are no columns: the code
is returned as it is.

The table's format is CPython's (Objects/locations.md): entries of 1 to 8 code
units whose first byte holds a kind and a length, then (signed) varints of
6-bit chunks. Entries are decoded to (length, line, end line, column, end
column) and written back in the long form, which holds any position.
"""

_NO_LOCATION, _NO_COLUMNS, _LONG = 15, 13, 14
_ONE_LINE = (10, 11, 12)


class _Reader(object):
    def __init__(self, data):
        self.data, self.pos = data, 0

    def byte(self):
        value = self.data[self.pos]
        self.pos += 1
        return value

    def varint(self):
        read = self.byte()
        value, shift = read & 63, 0
        while read & 64:
            read = self.byte()
            shift += 6
            value |= (read & 63) << shift
        return value

    def signed_varint(self):
        value = self.varint()
        return -(value >> 1) if value & 1 else value >> 1


def decode(table, first_line):
    """The entries of a 3.11+ location table: (length, line, end_line, col, end_col).

    A missing value is None, as in ``code.co_positions()``.
    """
    reader, line, entries = _Reader(table), first_line, []
    while reader.pos < len(table):
        first = reader.byte()
        kind, length = (first >> 3) & 15, (first & 7) + 1
        if kind == _NO_LOCATION:
            entries.append((length, None, None, None, None))
            continue
        if kind == _LONG:
            line += reader.signed_varint()
            end_line = line + reader.varint()
            col, end_col = reader.varint() - 1, reader.varint() - 1
        elif kind == _NO_COLUMNS:
            line += reader.signed_varint()
            end_line, col, end_col = line, -1, -1
        elif kind in _ONE_LINE:
            line += kind - 10
            end_line, col, end_col = line, reader.byte(), reader.byte()
        else:  # short form: same line, column < 80, up to 15 wide
            second = reader.byte()
            end_line, col = line, kind << 3 | second >> 4
            end_col = col + (second & 15)
        entries.append((length, line, end_line, None if col < 0 else col,
                        None if end_col < 0 else end_col))
    return entries


def _varint(value, out):
    while value >= 64:
        out.append(64 | (value & 63))
        value >>= 6
    out.append(value)


def _signed_varint(value, out):
    _varint((-value) << 1 | 1 if value < 0 else value << 1, out)


def encode(entries, first_line):
    """A location table holding ``entries`` (as ``decode`` returns them)."""
    out, previous = bytearray(), first_line
    for length, line, end_line, col, end_col in entries:
        if line is None:
            out.append(0x80 | _NO_LOCATION << 3 | (length - 1))
            continue
        out.append(0x80 | _LONG << 3 | (length - 1))
        _signed_varint(line - previous, out)
        _varint(end_line - line, out)
        _varint(0 if col is None else col + 1, out)
        _varint(0 if end_col is None else end_col + 1, out)
        previous = line
    return bytes(out)


def _shifted(entry, shifts):
    length, line, end_line, col, end_col = entry
    if line is not None:
        if col is not None:
            col = max(col + shifts.get(line, 0), 0)
        if end_col is not None:
            end_col = max(end_col + shifts.get(end_line, 0), 0)
    return length, line, end_line, col, end_col


def shift_columns(code, shifts):
    """``code`` (and the code objects in it) with columns moved by ``shifts``.

    ``shifts`` maps a line number to the number of columns to add on it.
    """
    if not shifts or not hasattr(code, 'co_positions'):
        return code
    consts = tuple(shift_columns(c, shifts) if hasattr(c, 'co_code') else c
                   for c in code.co_consts)
    entries = decode(code.co_linetable, code.co_firstlineno)
    table = encode([_shifted(e, shifts) for e in entries], code.co_firstlineno)
    return code.replace(co_consts=consts, co_linetable=table)


def relocate(code, line_of, kept, shifts):
    """``code`` (and the code objects in it) compiled from a translation, placed in the file.

    ``line_of`` maps a line of the translation to the file's line; ``kept``
    holds the lines of the translation that are the file's line as it is (but
    for Python 2's tab rule, whose ``shifts`` apply, by the file's line): their
    columns stay, every other position loses its columns (a traceback then
    shows the file's line without marks under it, as it cannot point into it).
    """
    if not hasattr(code, 'co_positions'):  # before 3.11 (not Debian 12's): the translation's lines
        return code
    consts = tuple(relocate(c, line_of, kept, shifts) if hasattr(c, 'co_code') else c
                   for c in code.co_consts)
    entries = []
    for length, line, end_line, col, end_col in decode(code.co_linetable, code.co_firstlineno):
        if line is not None:
            new_line = line_of(line)
            new_end = max(line_of(end_line), new_line) if end_line is not None else new_line
            if line in kept and end_line in kept:
                col = None if col is None else max(col + shifts.get(new_line, 0), 0)
                end_col = None if end_col is None else max(end_col + shifts.get(new_end, 0), 0)
            else:
                col = end_col = None
            line, end_line = new_line, new_end
        entries.append((length, line, end_line, col, end_col))
    first = line_of(code.co_firstlineno)
    return code.replace(co_consts=consts, co_firstlineno=first,
                        co_linetable=encode(entries, first))


"""A submission's file read as text, as the plan reads them all (no ROS):
the start of it (a file bigger than that is not a README, a launch file or a
script a person reads), undecodable bytes replaced, an unreadable file as
empty: a student's odd file never stops the planning."""

READ_LIMIT = 1 << 20      # bytes of one file read


def read_text(path, limit=READ_LIMIT):
    """The first ``limit`` bytes of ``path`` as text ('' if it cannot be read)."""
    try:
        with open(path, errors='replace') as f:
            return f.read(limit)
    except OSError:
        return ''

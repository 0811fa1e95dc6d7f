"""A submission's file read as text, as the plan reads them all (no ROS):
the start of it (a file bigger than that is not a README, a launch file or a
script a person reads), undecodable bytes replaced, an unreadable file as
empty: a student's odd file never stops the planning. And which of a
package's files are Python; and what the plan estimates of each built submission
before its run (:func:`of_built`)."""
import os

from exp_assignment2.grading.entry.unpacking import SubmissionError

READ_LIMIT = 1 << 20      # bytes of one file read


def read_text(path, limit=READ_LIMIT):
    """The first ``limit`` bytes of ``path`` as text ('' if it cannot be read)."""
    try:
        with open(path, errors='replace') as f:
            return f.read(limit)
    except OSError:
        return ''


def python_files(folder, skipped=()):
    """The Python files under ``folder``, in order: ``.py`` files and scripts
    whose first line runs python (a link to one too: an entry's copy keeps only
    links inside it); no hidden folder, none named in ``skipped``."""
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith('.') and d not in skipped)
        for name in sorted(files):
            path = os.path.join(root, name)
            if not os.path.isfile(path):
                continue
            if name.endswith('.py') or is_python_script(path):
                yield path


def is_python_script(path):
    try:
        with open(path, 'rb') as f:
            first = f.readline(200)
    except OSError:
        return False
    return first.startswith(b'#!') and b'python' in first


def of_built(runs, copies, read):
    """{name: read(root, folders)} of each submission of ``runs`` that builds
    packages (``folders``: them, relative to ``root``, the teacher's side's copy),
    read once, where it says something: what the plan estimates of a run before it
    starts (busy loops, cameras). A submission that cannot be read, or whose reading
    raises, is left out: an estimate never ends a grading."""
    found = {}
    for name, run in {run.spec.name: run for run in runs}.items():
        if not run.spec.build or run.spec.refused or run.spec.rejected:
            continue
        try:
            root = copies.of(run.submission).taken().root
        except SubmissionError:
            continue
        try:
            value = read(root, run.spec.build)
        except Exception:   # noqa: BLE001 -- an estimate only: never the grading's end
            continue
        if value:
            found[name] = value
    return found

"""How the Python 2 tests read and run a file as the original-code environment
does, in this interpreter (not a test by itself)."""
import contextlib
import io
import os
import sys
import textwrap

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, 'src', 'exp_assignment2', 'original_env', 'startup'))

import exp2_py2_read  # noqa: E402

NODE = '/students/pkg/scripts/node.py'


def read(source, path=NODE):
    data = textwrap.dedent(source).encode() if isinstance(source, str) else source
    return exp2_py2_read.read(data, path)


def run(source, path=NODE, stdin=''):
    """(namespace, what it printed) of ``source`` run as the environment reads it."""
    reading = read(source, path)
    assert reading is not None and reading.code is not None
    namespace, out = {'__name__': '__main__'}, io.StringIO()
    old_stdin, sys.stdin = sys.stdin, io.StringIO(stdin)
    try:
        with contextlib.redirect_stdout(out):
            exec(reading.code, namespace)
    finally:
        sys.stdin = old_stdin
    return namespace, out.getvalue()

"""Loops of a submission's Python that can go round without waiting (no ROS).

A student's ``while not self.arrived: pass``, or a state's loop that sleeps in
one branch and not in the other, keeps a core busy for as long as it goes round:
on a real class such a run cost 1.4 to 1.7 cores where the others cost 0.3 to
0.9, and a run of it started beside another before its cost was measured starved
both. The admission (run.admission) counts a submission with such a loop dearer
until its own run says what it costs.

A ``while`` loop is busy when some path through its body comes back to its test
(the end, or a ``continue``) without calling anything that waits (``sleep``,
``spin``, ``waitKey``, ``wait_for_*``, a service call, ...); a loop inside it
that waits counts as waiting. Python 2 files are read through the original
environment's translation (the same fixers its nodes run through), tabs as
Python 2 read them; 2to3 is slow (0.03 to 0.04 s a kilobyte), so only files of
at most MOST_TRANSLATED bytes are translated, for at most TRANSLATION_TIME s a
submission: a file not read is not known to loop.
"""
import ast
import os
import sys
import time

from exp_assignment2.grading.entry.reading import of_built, python_files

WAITS = frozenset((
    'sleep', 'wait', 'spin', 'spin_once', 'waitKey', 'wait_for_result', 'wait_for_server',
    'wait_for_message', 'wait_for_service', 'wait_for_transform', 'waitForTransform',
    'get_result', 'send_goal_and_wait', 'join', 'input', 'raw_input', 'recv', 'select',
    'get', 'acquire', 'readline', 'read', 'getch', 'call', 'imshow', 'lookup_transform'))
MOST_FILES = 200            # Python files read of one submission
MOST_BYTES = 256 * 1024     # of one file
# 2to3 takes 0.03 to 0.04 s a kilobyte: a file it translates, and its time for one submission
MOST_TRANSLATED = 64 * 1024
TRANSLATION_TIME = 3.0      # s (a real submission: under 1)


def _name(call):
    func = call.func
    return func.attr if isinstance(func, ast.Attribute) else \
        func.id if isinstance(func, ast.Name) else None


def _waits(node):
    """Does ``node`` call something that waits (outside functions it defines)?"""
    stack = [node]
    while stack:
        here = stack.pop()
        if isinstance(here, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            continue
        if isinstance(here, ast.Call) and _name(here) in WAITS:
            return True
        stack.extend(ast.iter_child_nodes(here))
    return False


def _path(stmts):
    """How a pass through ``stmts`` ends: 'waits' (every way waits first), 'leaves' (a
    break, return or raise first), 'busy' (a continue before any wait) or 'falls' (it
    reaches the end, some way without waiting)."""
    for stmt in stmts:
        if isinstance(stmt, (ast.Break, ast.Return, ast.Raise)):
            return 'leaves'
        if isinstance(stmt, ast.Continue):
            return 'busy'
        if isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            continue
        if isinstance(stmt, ast.If) and not _waits(stmt.test):
            ways = {_path(stmt.body), _path(stmt.orelse)}
            if 'busy' in ways:
                return 'busy'
            if 'falls' not in ways:
                return 'waits' if 'waits' in ways else 'leaves'
            continue
        if isinstance(stmt, (ast.Try, ast.With)):
            ending = _path(stmt.body)
            if ending != 'falls':
                return ending
            if isinstance(stmt, ast.Try) and _waits(ast.Module(body=stmt.finalbody,
                                                               type_ignores=[])):
                return 'waits'
            continue
        if _waits(stmt):
            return 'waits'
    return 'falls'


def in_tree(tree):
    """Lines of the ``while`` loops of ``tree`` that can go round without waiting."""
    return sorted(node.lineno for node in ast.walk(tree)
                  if isinstance(node, ast.While) and not _waits(node.test) and
                  _path(node.body) in ('falls', 'busy'))


def _tree(text, path, budget=None):
    """The module's tree as Python 3 reads it, else as the original environment
    runs a Python 2 file (translated, tabs of 8; a file of at most MOST_TRANSLATED
    bytes, while ``budget``, a :class:`Budget`, has time left), else None."""
    for version in (text, text.expandtabs(8)):
        for read in (lambda: version, lambda: _translate(version, path, budget)):
            source = read()
            try:
                if source is not None:
                    return ast.parse(source)
            except (SyntaxError, ValueError, RecursionError, MemoryError):
                pass
    return None


class Budget(object):
    """The time left to translate one submission's Python 2 files (monotonic s)."""

    def __init__(self, seconds=TRANSLATION_TIME):
        self.until = time.monotonic() + seconds

    def left(self):
        return time.monotonic() < self.until


def _translate(text, path, budget=None):
    if len(text) > MOST_TRANSLATED or (budget is not None and not budget.left()):
        return None
    here = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__)))), 'original_env', 'startup')
    if here not in sys.path:
        sys.path.append(here)
    try:
        import exp2_py2_translate
        translation = exp2_py2_translate.translate(text, path)
    except Exception:       # noqa: BLE001 -- a file the translation cannot read: not known
        return None
    return translation.text if translation is not None else None


def in_folders(root, folders):
    """[(file relative to ``root``, line)] of the busy loops in the Python of
    ``folders`` (relative to ``root``: the packages a run builds)."""
    found, read, budget = [], 0, Budget()
    for folder in folders:
        for path in python_files(os.path.join(root, folder)):
            if read >= MOST_FILES:
                return found
            read += 1
            try:
                if os.path.getsize(path) > MOST_BYTES:
                    continue
                with open(path, encoding='utf-8', errors='replace') as f:
                    text = f.read()
            except OSError:
                continue
            tree = _tree(text, path, budget)
            try:
                lines = in_tree(tree) if tree is not None else []
            except RecursionError:      # a chain of thousands of elifs: not known to loop
                lines = []
            found += [(os.path.relpath(path, root), line) for line in lines]
    return found


def of_runs(runs, copies):
    """{name: [(file, line)]} of the submissions of ``runs`` whose built packages
    have a busy loop (entry.reading.of_built)."""
    return of_built(runs, copies, in_folders)

"""The stderr lines naming the files that were read as Python 2 read them.

A program reads most of its files in one burst: the script, then what its
first statements import, and what those import. The line names them together
once the burst is over, that is when the code that imported (the script's
top level, or a function importing lazily) goes on to a statement that is not
part of its imports, or returns; at exit at the latest. A file read later in
the run (an import inside a function called later) gets its own line then.

    [original-env] read with Python 2's tab rule: state_machine.py, helper.py
    [original-env] read as Python 2 (translated in memory): dog.py

(the first for files only re-indented, the second for files translated by
2to3's fixers, with the tab rule too where it applied: exp2_py2_read.py).

Statements taken as part of the imports: ``import``, ``from ... import``, a
string (docstring), ``pass``, ``sys.path.append(...)``/``insert``/``extend``,
and ``if``/``try`` blocks made only of these.

The end of the burst is seen with a trace function on that one frame, only in
a process that read a file with the tab rule and only until the line is
written; when a debugger or coverage tool is already tracing, the line is
written at once instead.
"""
import ast
import atexit
import linecache
import os
import sys
import threading

import exp2_py2_indent

PREFIX = "[original-env] read with Python 2's tab rule: "
PREFIXES = {'tabs': PREFIX, 'python2': '[original-env] read as Python 2 (translated in memory): '}

_lock = threading.Lock()
_pending = []
_state = {'watching': False, 'atexit': False, 'tracer': None}
_trees = {}  # file name -> its module's AST (None if unreadable)
_HERE = os.path.dirname(os.path.abspath(__file__))
_OWN_FILES = frozenset(os.path.join(_HERE, name) for name in (
    'exp2_tab_report.py', 'exp2_tab_import.py', 'exp2_py2_read.py', 'exp2_py2_translate.py'))
_IMPORTLIB_DIR = os.path.join(os.path.dirname(os.__file__), 'importlib') + os.sep
_RUNPY = os.path.join(os.path.dirname(os.__file__), 'runpy.py')


def note(path, script=False, how='tabs'):
    """Record that ``path`` was read as Python 2 read it ('tabs': with the tab rule;
    'python2': translated); the line follows (see above).

    ``script``: ``path`` is a script about to run, not a module being imported.
    """
    with _lock:
        if (path, how) not in _pending:
            _pending.append((path, how))
        if _state['watching']:
            return
        _state['watching'] = True
        if not _state['atexit']:
            atexit.register(flush)
            _state['atexit'] = True
    if sys.gettrace() is not None:  # someone else traces this thread: do not interfere
        flush()
        return
    importer = None if script else _importer(sys._getframe(1))
    if importer is None:
        # Nobody imports it: a script or ``python -m`` module, about to run.
        _state['tracer'] = _module_code_tracer(path)
    else:
        importer.f_trace = _watch
        _state['tracer'] = _untraced
    sys.settrace(_state['tracer'])


def flush():
    """Write the lines for the files recorded so far, if any."""
    with _lock:
        noted = list(_pending)
        del _pending[:]
        _state['watching'] = False
    lines = []
    for how in ('tabs', 'python2'):
        names = [_shown(path) for path, kind in noted if kind == how]
        if names:
            lines.append(PREFIXES[how] + ', '.join(names) + '\n')
    if not lines:
        return
    try:
        sys.stderr.write(''.join(lines))
        sys.stderr.flush()
    except (AttributeError, OSError, ValueError):  # no stderr, or closed
        pass


def _shown(path):
    """``path`` relative to the current directory when it is below it (and that is not /)."""
    try:
        cwd = os.getcwd()
        relative = os.path.relpath(path, cwd)
    except (OSError, ValueError):
        return path
    return path if relative.startswith(os.pardir) or cwd == os.sep else relative


def _is_machinery(frame):
    name = frame.f_code.co_filename
    return (name.startswith('<frozen importlib') or name == '<frozen runpy>'
            or name.startswith(_IMPORTLIB_DIR) or name == _RUNPY or name in _OWN_FILES)


def _importer(frame):
    """The frame that started the outermost import under way, or None."""
    found = None
    while frame is not None:
        caller = frame.f_back
        if caller is not None and _is_machinery(frame) and not _is_machinery(caller):
            found = caller
        frame = caller
    return found


def _untraced(frame, event, arg):
    return None


def _module_code_tracer(path):
    def tracer(frame, event, arg):
        code = frame.f_code
        if event == 'call' and code.co_name == '<module>' and code.co_filename == path:
            return _watch
        return None
    return tracer


def _watch(frame, event, arg):
    """Local trace function of the importing frame: waits for the end of its imports."""
    if event == 'line' and _part_of_imports(frame.f_code.co_filename, frame.f_lineno):
        return _watch
    if event in ('line', 'return'):
        frame.f_trace = None
        if sys.gettrace() is _state['tracer']:
            sys.settrace(None)
        flush()
        return None
    return _watch


def _tree(filename):
    if filename not in _trees:
        text = exp2_py2_indent.python2_indentation(''.join(linecache.getlines(filename)))[0]
        try:
            _trees[filename] = ast.parse(text, filename)
        except (SyntaxError, ValueError):
            _trees[filename] = _translated_tree(text, filename)
    return _trees[filename]


def _translated_tree(text, filename):
    """The AST of the file's translation, on the file's lines (or None)."""
    import exp2_py2_translate
    translation = exp2_py2_translate.translate(text, filename)
    try:
        tree = ast.parse(translation.text, filename) if translation else None
    except (SyntaxError, ValueError):
        return None
    for node in ast.walk(tree) if tree else ():
        if getattr(node, 'lineno', None):
            node.lineno = translation.original_line(node.lineno)
            node.end_lineno = max(translation.original_line(node.end_lineno), node.lineno)
    return tree


def _statement_at(tree, line):
    """The innermost statement of ``tree`` that spans ``line``."""
    found = None
    for node in ast.walk(tree):  # breadth first: a nested statement comes after its parent
        if isinstance(node, ast.stmt) and node.lineno <= line <= node.end_lineno:
            if found is None or node.end_lineno - node.lineno <= found.end_lineno - found.lineno:
                found = node
    return found


def _part_of_imports(filename, line):
    tree = _tree(filename)
    statement = _statement_at(tree, line) if tree is not None else None
    return statement is not None and _is_import_statement(statement)


def _is_sys_path_call(node):
    func = node.func if isinstance(node, ast.Call) else None
    return (isinstance(func, ast.Attribute) and func.attr in ('append', 'insert', 'extend')
            and isinstance(func.value, ast.Attribute) and func.value.attr == 'path'
            and isinstance(func.value.value, ast.Name) and func.value.value.id == 'sys')


def _is_import_statement(node):
    if isinstance(node, (ast.Import, ast.ImportFrom, ast.Pass)):
        return True
    if isinstance(node, ast.Expr):
        value = node.value
        return (isinstance(value, ast.Constant) and isinstance(value.value, str)
                or _is_sys_path_call(value))
    if isinstance(node, ast.If):
        bodies = [node.body, node.orelse]
    elif isinstance(node, ast.Try):
        bodies = [node.body, node.orelse, node.finalbody] + [h.body for h in node.handlers]
    else:
        return False
    return all(_is_import_statement(child) for body in bodies for child in body)

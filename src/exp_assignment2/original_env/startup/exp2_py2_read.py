"""How the original-code environment reads a Python file: as Python 3 does, else as Python 2 did.

:func:`read` decides for the bytes of one file, in memory (the file is never
changed), for the import hook (exp2_tab_import.py), the script runner
(exp2_tab_script.py) and catkin's relay scripts:

1. Python 3 compiles it and it uses nothing only Python 2 had
   (exp2_py2_names.py; only asked of files outside the interpreter's own
   libraries): it runs as it is;
2. Python 3 refuses it for tabs in its indentation: it is re-indented with
   Python 2's tab rule (exp2_py2_indent.py); if that compiles and uses
   nothing only Python 2 had, that is all ('tabs');
3. otherwise (a SyntaxError such as ``print "x"``, or a name only Python 2
   had): it is translated by 2to3's fixers and this environment's
   (exp2_py2_translate.py), after the tab rule if it applied ('python2').
   What Python 2.7's compiler accepted with a warning and Python 3's
   refuses (a late ``global``, ``import *`` in a function) is compiled as
   Python 2 read it (exp2_py2_lenient.py). The code is compiled from the
   translation and placed back on the file's lines
   (exp2_code_columns.relocate), so tracebacks show the student's line
   numbers and lines.

A file 2to3 cannot read either gets Python 3's own error. A translation that
does not compile gets its error on the file's line: the import system
compiles the translation laid out on the file's lines (``Reading.source``).
"""
import io
import os
import sysconfig
import tokenize
import warnings

import exp2_code_columns
import exp2_py2_indent

STARTUP = os.path.dirname(os.path.abspath(__file__))


class Reading(object):
    """``source``: bytes for the import system; ``code``: what runs, or None when
    compiling ``source`` raises the file's error; ``how``: None (as it is),
    'tabs' or 'python2'."""

    def __init__(self, source, code, how):
        self.source, self.code, self.how = source, code, how


def _system_directories():
    paths = sysconfig.get_paths()
    found = {os.path.realpath(paths[k]) for k in ('stdlib', 'platstdlib', 'purelib', 'platlib')
             if paths.get(k)}
    found.add(STARTUP)
    found.update(('/usr/bin', '/bin', '/usr/sbin', '/sbin', '/usr/local/bin', '/opt/ros'))
    return tuple(d.rstrip(os.sep) + os.sep for d in found)


_SYSTEM = _system_directories()


def is_system_path(path):
    """Is ``path`` a file of the interpreter's own libraries, of an installed
    package (site-packages, dist-packages, the system's programs, /opt/ros) or
    of this environment's start-up?"""
    if not path or path.startswith('<frozen'):
        return True
    path = os.path.abspath(path)
    return (path.startswith(_SYSTEM) or os.sep + 'dist-packages' + os.sep in path or
            os.sep + 'site-packages' + os.sep in path)


def _compile(source, path, optimize):
    return compile(source, path, 'exec', dont_inherit=True, optimize=optimize)


def switches(environ=None):
    """(tab rule, Python 2 translation): on unless EXP2_TAB_RULE, EXP2_PY2 is 0."""
    environ = os.environ if environ is None else environ
    return environ.get('EXP2_TAB_RULE', '1') != '0', environ.get('EXP2_PY2', '1') != '0'


def read(data, path, in_package=False, optimize=-1, tabs=True, python2=True):
    """The :class:`Reading` of a file's bytes ``data`` (``path`` names it in
    code and errors); None when Python 3's compiler should just report its error.

    ``in_package``: the file is a module of a package (Python 2's implicit
    relative imports are translated). ``tabs``, ``python2``: the tab rule,
    the translation (:func:`switches`).
    """
    try:
        code = _compile(data, path, optimize)
    except (SyntaxError, ValueError) as refused:
        if isinstance(refused, ValueError):       # null bytes: Python says so itself
            return None
        indentation = isinstance(refused, IndentationError)
    else:
        if not python2 or is_system_path(path) or not _names_python2(code, data):
            return Reading(data, code, None)
        return _translated(data, path, {}, in_package, optimize) or Reading(data, code, None)
    source, shifts, how = data, {}, None
    if tabs and exp2_py2_indent.has_tab_indentation(data):
        reindented = exp2_py2_indent.python2_source(data)
        if reindented is not None:
            (source, shifts), how = reindented, 'tabs'
            try:
                code = _compile(source, path, optimize)
            except IndentationError:    # Python 2 could not indent it either: its error
                return Reading(source, None, how)
            except (SyntaxError, ValueError):
                pass
            else:
                if not python2 or is_system_path(path) or not _names_python2(code, source):
                    return Reading(source, exp2_code_columns.shift_columns(code, shifts), how)
    translated = _translated(source, path, shifts, in_package, optimize) if python2 else None
    if translated is not None:
        return translated
    # Python 3's own error, on the file's (re-indented, if that was its first fault) lines
    return Reading(source, None, how) if how and indentation else None


def _names_python2(code, data):
    import exp2_py2_names
    if not exp2_py2_names.may_name_python2(code):
        return False
    import ast
    try:
        return bool(exp2_py2_names.python2_names(ast.parse(data)))
    except (SyntaxError, ValueError, RecursionError):
        return False


def _decoded(data):
    encoding = tokenize.detect_encoding(io.BytesIO(data).readline)[0]
    text = data.decode(encoding)
    return text.replace('\r\n', '\n').replace('\r', '\n'), encoding


def _translated(data, path, shifts, in_package, optimize):
    """The 'python2' :class:`Reading` of ``data`` (already re-indented by the tab
    rule where ``shifts`` says), or None when 2to3 cannot parse it."""
    import exp2_py2_lenient
    import exp2_py2_runtime
    import exp2_py2_translate
    try:
        text, encoding = _decoded(data)
    except (SyntaxError, UnicodeDecodeError, LookupError):
        return None
    translation = exp2_py2_translate.translate(text, path, in_package)
    if translation is None:
        return None
    exp2_py2_runtime.install()
    lines = text.split('\n')
    new_lines = translation.text.split('\n')
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter('always')
            code = exp2_py2_lenient.compile_lenient(translation.text, path, optimize)
    except SyntaxError:
        return Reading(_on_file_lines(translation, new_lines, encoding), None, 'python2')
    for warning in caught:      # said again, on the file's lines
        warnings.warn_explicit(warning.message, warning.category, path,
                               translation.original_line(warning.lineno or 1))
    kept = {number for number, (line, origin) in enumerate(
        zip(new_lines, translation.lines), 1) if origin is not None and
        0 < origin <= len(lines) and lines[origin - 1] == line}
    code = exp2_code_columns.relocate(code, translation.original_line, kept, shifts)
    return Reading(translation.text.encode(encoding), code, 'python2')


def _on_file_lines(translation, new_lines, encoding):
    """The translation with each line on the file's line (lines a fixer made up,
    or that would come before their line, left out): compiling it raises the
    translation's error on the file's line."""
    placed = []
    for line, origin in zip(new_lines, translation.lines):
        if origin is None or origin <= len(placed):
            continue
        placed.extend([''] * (origin - 1 - len(placed)))
        placed.append(line)
    return '\n'.join(placed).encode(encoding, 'surrogateescape') + b'\n'

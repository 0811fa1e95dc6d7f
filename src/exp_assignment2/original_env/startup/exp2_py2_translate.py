"""Python 2 source translated to Python 3 text, with where each line came from.

:func:`translate` runs 2to3's fixers (PyPI's ``fissix``, the maintained fork,
when it is installed, else the standard library's ``lib2to3``, whose
deprecation warning is silenced) and this environment's (exp2_py2_fixers.py)
on a file's text, in memory, and exp2_py2_lenient's renaming of
``async``/``await`` names. Left out of 2to3's default set: ``fix_import``
(``import helper`` -> ``from . import helper``) except for a module of a
package, where Python 2's implicit relative import did that, and
``fix_numliterals`` (replaced).

Some fixers add lines (``except E, (a, b):`` unpacks on a new line,
``reduce`` gets ``from functools import reduce``, ``from urllib import a, b``
becomes two imports). The translated text is therefore returned with
``lines``: for each of its lines, the line of the file it came from, or None
for a line a fixer made up. It is read from the parse tree: every token the
parser read keeps its line, also when a fixer moves or copies it.
"""
import warnings

with warnings.catch_warnings():
    warnings.simplefilter('ignore', DeprecationWarning)  # lib2to3 of Python 3.9 to 3.12
    warnings.simplefilter('ignore', PendingDeprecationWarning)
    try:
        # fissix caches its grammar under the user's cache directory: a home it
        # cannot write (a read-only sandbox) makes its import fail, lib2to3's does not
        import fissix as lib
        from fissix import refactor
        from fissix.pgen2 import parse as _parse, token as _token, tokenize as _tokenize
    except Exception:
        import lib2to3 as lib
        from lib2to3 import refactor
        from lib2to3.pgen2 import parse as _parse, token as _token, tokenize as _tokenize

import exp2_py2_fixers
import exp2_py2_lenient

BACKEND = lib.__name__
LEFT_OUT = ('fix_import', 'fix_numliterals')
# what 2to3's parser raises for a text it cannot read
PARSE_ERRORS = (_parse.ParseError, _tokenize.TokenError, IndentationError, SyntaxError)
_tools = {}


class Translation(object):
    """The translated ``text`` and ``lines`` (see the module's docstring)."""

    def __init__(self, text, lines, changed):
        self.text, self.lines, self.changed = text, lines, changed

    def original_line(self, line):
        """The file's line for ``line`` of the translation (a made-up line: the one before)."""
        for index in range(min(line, len(self.lines)) - 1, -1, -1):
            if self.lines[index] is not None:
                return self.lines[index]
        return 1


class _Tool(refactor.RefactoringTool):
    """2to3's RefactoringTool with this environment's fixers added to its own."""

    def get_fixers(self):
        pre, post = super().get_fixers()
        for cls in exp2_py2_fixers.make(lib) + exp2_py2_lenient.make(lib):
            fixer = cls(self.options, self.fixer_log)
            (pre if fixer.order == 'pre' else post).append(fixer)
        pre.sort(key=lambda f: f.run_order)
        post.sort(key=lambda f: f.run_order)
        return pre, post

    def log_error(self, msg, *args, **kwds):
        raise  # noqa: PLE0704 (re-raises the parse error being handled, as 2to3 does)


def _tool(print_function, in_package):
    key = (print_function, in_package)
    if key not in _tools:
        names = [name for name in refactor.get_fixers_from_package(BACKEND + '.fixes')
                 if name.rsplit('.', 1)[-1] not in LEFT_OUT or
                 (in_package and name.endswith('.fix_import'))]
        with warnings.catch_warnings():
            warnings.simplefilter('ignore')
            _tools[key] = _Tool(names, {'print_function': print_function})
    return _tools[key]


def translate(text, path='<string>', in_package=False):
    """The :class:`Translation` of ``text`` (a str, lines ending in '\\n'), or None
    when 2to3 cannot parse it (neither Python 2 nor what 2to3 reads of Python 3).

    ``in_package``: ``path`` is a module of a package (``fix_import`` applies).
    """
    if not text.endswith('\n'):
        text += '\n'
    tree = None
    for print_function in (False, True):  # Python 3's print(..., end='') needs the second
        try:
            with warnings.catch_warnings():
                warnings.simplefilter('ignore')
                tree = _tool(print_function, in_package).refactor_string(text, path)
            break
        except PARSE_ERRORS:
            continue
        except RecursionError:  # a very deeply nested expression
            return None
    if tree is None:
        return None
    return Translation(str(tree), _origins(tree), tree.was_changed)


def _origins(tree):
    """For each line of ``str(tree)``: the source line it came from, or None."""
    skip = (_token.NEWLINE, _token.INDENT, _token.DEDENT, _token.ENDMARKER)
    found = {}      # line of the translation -> line of the source (its first token's)
    made_up = set()
    line = 1
    for leaf in tree.leaves():
        line += leaf.prefix.count('\n')
        if leaf.type not in skip and leaf.value:
            if leaf.lineno > 0:
                found.setdefault(line, leaf.lineno)
            else:
                made_up.add(line)
        line += leaf.value.count('\n')
    total = line
    next_found, upcoming = {}, None     # line -> the source line of the next line with a token
    for number in range(total, 0, -1):
        next_found[number] = upcoming
        upcoming = found.get(number, upcoming)
    lines, expected = [], 1     # the source line that comes next
    for number in range(1, total + 1):
        if number in found:
            lines.append(found[number])
            expected = found[number] + 1
        elif number in made_up:
            # made up in place of a source line (``from urllib import a`` rewritten) or
            # added to it (``from functools import reduce``, the second import of two)
            upcoming = next_found[number]
            if upcoming is None or expected < upcoming:
                lines.append(expected)
                expected += 1
            else:
                lines.append(None)
        else:   # a blank line, a comment, the inside of a string: the next one
            lines.append(expected)
            expected += 1
    return lines

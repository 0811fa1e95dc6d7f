"""What Python 2.7's compiler accepted with at most a warning and Python 3's refuses.

Python 3 made errors of a few things Python 2.7 compiled, so a node that ran
on Kinetic or Melodic would die before its first line. Read as Python 2
(exp2_py2_read.py), they run as Python 2 ran them, on the student's lines:

* ``global x`` after ``x`` is assigned or used in the same function (or class
  body, or module): Python 2 warned (``SyntaxWarning: name 'x' is assigned to
  before global declaration``) and took the declaration for the whole block.
  :func:`compile_lenient` moves it to the top of its block (after a
  docstring, and after ``from __future__`` imports in a module), in the
  parse tree, so no line moves;
* ``from module import *`` in a function: Python 2 warned (``import * only
  allowed at module level``) and bound the names when the line ran; here
  they are bound in the module's globals, which the function reads
  (``_exp2_py2.import_star``; a global of the same name is overwritten, where
  Python 2 shadowed it in that function only);
* ``async`` and ``await`` as names (keywords since Python 3.7): :func:`make`'s
  2to3 fixer renames them ``async_`` and ``await_`` in every file it reads,
  so a module and its users agree.

Each warning Python 2 gave is given again, on the file's line. Not handled,
too unlikely in a ROS node: ``True``/``False`` assigned to, ``nonlocal`` as a
name (2to3's parser refuses it), ``exec`` changing a function's locals, a
list comprehension's variable read after it.
"""
import ast
import re
import warnings

RUNTIME = '_exp2_py2'
KEYWORDS = ('async', 'await')
# what Python 3's compiler says of each (the first one it meets)
REFUSALS = re.compile(r"name '\w+' is (assigned to before|used prior to) global declaration|"
                      r"import \* only allowed at module level")
STAR = 'import * only allowed at module level'
_BLOCKS = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)


def make(lib):
    """The 2to3 fixer renaming ``async``/``await`` names, built on ``lib`` (fissix or lib2to3)."""
    from importlib import import_module
    fixer_base = import_module(lib.__name__ + '.fixer_base')
    util = import_module(lib.__name__ + '.fixer_util')
    token = import_module(lib.__name__ + '.pgen2.token')

    class FixExp2Keywords(fixer_base.BaseFix):
        _accept_type = token.NAME     # 2to3's ASYNC/AWAIT tokens (Python 3 code) are others
        order = 'pre'

        def match(self, node):
            return node.value in KEYWORDS

        def transform(self, node, results):
            return util.Name(node.value + '_', prefix=node.prefix)

    return [FixExp2Keywords]


def compile_lenient(text, path, optimize=-1):
    """``compile(text, path, 'exec')``; where Python 3 refuses one of the module's
    cases, compiled as Python 2 read it, with Python 2's warnings (on the lines
    of ``text``). Any other error is Python 3's."""
    try:
        return compile(text, path, 'exec', dont_inherit=True, optimize=optimize)
    except SyntaxError as refused:
        if not REFUSALS.search(str(refused.msg)):
            raise
    tree = ast.parse(text, path)
    said = []
    _Block(tree, said).settle()
    for message, line in sorted(said, key=lambda item: item[1]):
        warnings.warn_explicit(message, SyntaxWarning, path, line)
    return compile(tree, path, 'exec', dont_inherit=True, optimize=optimize)


class _Block(object):
    """A module, class or function body: its global declarations, the names
    bound and read in it before each, and its star imports."""

    def __init__(self, node, said):
        self.node, self.said = node, said
        self.declarations, self.stars, self.inner = [], [], []
        self.seen = {}      # name -> 'assigned to before' or 'used prior to', first seen
        self.late = []
        for statement in node.body:
            self._visit(statement, node)

    def settle(self):
        """Move the declarations up and replace the star imports, here and in inner blocks."""
        if self.late:
            self.said.extend(self.late)
            names = [name for declaration in self.declarations for name in declaration.names]
            for declaration in self.declarations:
                _replace(declaration, ast.copy_location(ast.Pass(), declaration))
            top = ast.copy_location(ast.Global(names=list(dict.fromkeys(names))),
                                    self.declarations[0])
            self.node.body.insert(_top(self.node), top)
        for star in self.stars:
            self.said.append((STAR, self.node.lineno))     # Python 2 named the def's line
            call = ast.Call(ast.Attribute(ast.Name(RUNTIME, ast.Load()), 'import_star',
                                          ast.Load()),
                            [ast.Constant(star.module or ''), ast.Constant(star.level or 0)], [])
            _replace(star, ast.fix_missing_locations(ast.copy_location(ast.Expr(call), star)))
        for block in self.inner:
            block.settle()

    def _visit(self, node, parent):
        node._exp2_parent = parent
        if isinstance(node, ast.Global):
            self.declarations.append(node)
            self.late.extend(("name '%s' is %s global declaration" % (name, self.seen[name]),
                              node.lineno) for name in node.names if name in self.seen)
            return
        if isinstance(node, _BLOCKS):
            self._bind(node.name)
            outer = node.decorator_list + (getattr(node, 'bases', []) +
                                           [k.value for k in getattr(node, 'keywords', [])])
            if hasattr(node, 'args'):
                outer += node.args.defaults + [d for d in node.args.kw_defaults if d]
            for part in outer:
                self._visit(part, node)
            self.inner.append(_Block(node, self.said))
            return
        if isinstance(node, ast.Lambda):    # a block that cannot declare: its defaults only
            for part in node.args.defaults:
                self._visit(part, node)
            return
        if isinstance(node, ast.ImportFrom) and any(a.name == '*' for a in node.names):
            if not isinstance(self.node, ast.Module):
                self.stars.append(node)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                self._bind((alias.asname or alias.name).split('.')[0])
        elif isinstance(node, ast.Name):
            if isinstance(node.ctx, ast.Load):
                self.seen.setdefault(node.id, 'used prior to')
            else:
                self._bind(node.id)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            self._bind(node.name)
        for child in ast.iter_child_nodes(node):
            self._visit(child, node)

    def _bind(self, name):
        self.seen[name] = 'assigned to before'


def _top(block):
    """Where a declaration goes in ``block``'s body: after its docstring and
    (a module's) ``from __future__`` imports."""
    body, index = block.body, 0
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
            and isinstance(body[0].value.value, str):
        index = 1
    while index < len(body) and isinstance(body[index], ast.ImportFrom) and \
            body[index].module == '__future__':
        index += 1
    return index


def _replace(node, new):
    """Put ``new`` where the statement ``node`` is in its parent's lists of statements."""
    parent = node._exp2_parent
    for field in ('body', 'orelse', 'finalbody', 'handlers'):
        statements = getattr(parent, field, None)
        if isinstance(statements, list) and any(s is node for s in statements):
            statements[[id(s) for s in statements].index(id(node))] = new
            return
    raise ValueError('statement not found in its parent')

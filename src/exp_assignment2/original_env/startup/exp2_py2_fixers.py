"""The fixers this environment adds to 2to3's, where Python 2's meaning is not 2to3's business.

2to3 translates syntax and names; it leaves ``/`` alone (a programmer was to
decide), ``0777L`` half done, and knows nothing of ``time.clock``,
``string.letters``, ``cmp``, ``file`` or Python 2's ``round``. These fixers
make the translated file compute what Python 2 computed, through
exp2_py2_runtime (the builtin ``_exp2_py2``), never adding a line:

* ``FixExp2Division``: ``a / b`` -> ``_exp2_py2.div(a, b)`` (``a // b`` for two
  integer literals, unchanged when one is a float literal), ``x /= y`` ->
  ``x = _exp2_py2.idiv(x, y)`` for a target without calls; nothing at all
  under ``from __future__ import division``;
* ``FixExp2Numbers``: ``0777L`` -> ``0o777``, ``10L`` -> ``10`` (replaces 2to3's
  fix_numliterals, which leaves ``0777L`` as ``0777``);
* ``FixExp2ModuleNames``: ``time.clock`` -> ``time.process_time`` (Python 2's
  ``clock`` was the process's CPU time on Linux), ``string.letters``,
  ``lowercase``, ``uppercase`` -> ``ascii_*``, ``string.maketrans`` ->
  ``str.maketrans``, the other functions of Python 2's ``string`` module ->
  ``_exp2_py2.string.*``; in a file that imports the module by its name;
* ``FixExp2Builtins``: ``cmp``, ``file`` and (called) ``round`` -> ``_exp2_py2.*``
  where the file binds no such name anywhere.

Every fixer is built on the 2to3 package the translation uses (``make``).
"""
import re

RUNTIME = '_exp2_py2'
STRING_FUNCTIONS = frozenset((
    'atoi', 'atol', 'atof', 'capitalize', 'expandtabs', 'find', 'rfind', 'index', 'rindex',
    'count', 'lower', 'upper', 'swapcase', 'strip', 'lstrip', 'rstrip', 'split', 'splitfields',
    'rsplit', 'replace', 'ljust', 'rjust', 'center', 'join', 'joinfields', 'zfill'))
# module -> {Python 2 attribute: (new module, new attribute)}
MODULE_NAMES = {
    'time': {'clock': ('time', 'process_time')},
    'string': dict({'letters': ('string', 'ascii_letters'),
                    'lowercase': ('string', 'ascii_lowercase'),
                    'uppercase': ('string', 'ascii_uppercase'),
                    'maketrans': ('str', 'maketrans')},
                   **{name: (RUNTIME + '.string', name) for name in STRING_FUNCTIONS}),
}
BUILTINS = ('cmp', 'file', 'round')
_INT = re.compile(r'^(?:0[xX][0-9a-fA-F]+|0[oO]?[0-7]*|0[bB][01]+|[1-9][0-9]*)[lL]?$')
_FLOAT = re.compile(r'^(?:[0-9]*\.[0-9]*(?:[eE][-+]?[0-9]+)?|[0-9]+[eE][-+]?[0-9]+)$')


def make(lib):
    """The fixer classes, built on ``lib`` (the fissix or lib2to3 package)."""
    from importlib import import_module
    fixer_base = import_module(lib.__name__ + '.fixer_base')
    util = import_module(lib.__name__ + '.fixer_util')
    pytree = import_module(lib.__name__ + '.pytree')
    token = import_module(lib.__name__ + '.pgen2.token')
    syms = import_module(lib.__name__ + '.pygram').python_symbols
    Leaf, Node, Name = pytree.Leaf, pytree.Node, util.Name

    def runtime(attr, prefix=''):
        """``_exp2_py2.attr`` as the leaves of a ``power`` node."""
        parts = attr.split('.')
        return [Name(RUNTIME, prefix=prefix)] + [Node(syms.trailer, [util.Dot(), Name(p)])
                                                   for p in parts]

    def call(attr, args, prefix):
        return Node(syms.power, runtime(attr, prefix) + [util.ArgList(args)])

    class FixExp2Division(fixer_base.BaseFix):
        PATTERN = "term< any+ > | expr_stmt< any '/=' any >"
        order = 'post'

        def start_tree(self, tree, filename):
            super().start_tree(tree, filename)
            self.skip = 'division' in getattr(tree, 'future_features', ())

        def match(self, node):
            if self.skip:
                return False
            if node.type == syms.term:
                return any(child.type == token.SLASH for child in node.children)
            return super().match(node)

        def transform(self, node, results):
            if node.type == syms.expr_stmt:
                return self._augmented(node)
            kids = list(node.children)
            prefix = kids[0].prefix
            for kid in kids:
                kid.remove()
            kids[0].prefix = ''
            pending = [kids[0]]
            for op, right in zip(kids[1::2], kids[2::2]):
                if op.type == token.SLASH:
                    left = pending[0] if len(pending) == 1 else Node(syms.term, pending)
                    pending = [self._divide(left, op, right)]
                else:
                    pending += [op, right]
            result = pending[0] if len(pending) == 1 else Node(syms.term, pending)
            result.prefix = prefix
            return result

        def _divide(self, left, op, right):
            kinds = [_literal_kind(side) for side in (left, right)]
            if 'float' in kinds:
                return Node(syms.term, [left, op, right])
            if kinds == ['int', 'int']:
                op.value = '//'
                return Node(syms.term, [left, op, right])
            comma = util.Comma()
            if '\n' in op.prefix:                # a line continuation before the '/' stays
                comma.prefix = op.prefix
            return call('div', [left, comma, right], '')

        def _augmented(self, node):
            target, op, value = node.children
            if not _without_calls(target):
                return None                     # evaluated twice: left as Python 3's /=
            prefix = target.prefix
            for kid in (target, op, value):
                kid.remove()
            copy = target.clone()
            copy.prefix = ''
            target.prefix = prefix
            comma = util.Comma()
            value_prefix = value.prefix
            value.prefix = ' '
            comma.prefix = ''
            assign = Leaf(token.EQUAL, '=', prefix=op.prefix)
            return Node(syms.expr_stmt, [target, assign,
                                         call('idiv', [copy, comma, value], value_prefix)])

    def _literal_kind(node):
        if node.type != token.NUMBER:
            return None
        if _INT.match(node.value):
            return 'int'
        return 'float' if _FLOAT.match(node.value) else None

    def _without_calls(target):
        if target.type == token.NAME:
            return True
        if target.type != syms.power or target.children[0].type != token.NAME:
            return False
        for trailer in target.children[1:]:
            if trailer.type != syms.trailer or trailer.children[0].value == '(':
                return False
            if any(n.type == syms.power for n in trailer.pre_order()):
                return False        # a call or an attribute chain inside a subscript
        return True

    class FixExp2Numbers(fixer_base.BaseFix):
        _accept_type = token.NUMBER
        order = 'pre'

        def match(self, node):
            return node.value[-1] in 'lL' or (node.value.startswith('0') and
                                             node.value[1:2].isdigit())

        def transform(self, node, results):
            value = node.value.rstrip('lL')
            if value.startswith('0') and value.isdigit() and len(set(value)) > 1:
                value = '0o' + value[1:]
            return util.Number(value, prefix=node.prefix)

    class FixExp2ModuleNames(fixer_base.BaseFix):
        PATTERN = ("power< mod=('time' | 'string') trailer< '.' attr=NAME > any* > | "
                   "import_from< 'from' mod=('time' | 'string') 'import' names=any >")
        order = 'pre'

        def start_tree(self, tree, filename):
            super().start_tree(tree, filename)
            self.imported = _modules_imported(tree)

        def transform(self, node, results):
            module = results['mod']
            module = module[0] if isinstance(module, list) else module
            table = MODULE_NAMES[module.value]
            if 'attr' not in results:
                return self._from_import(results['names'], table)
            attr = results['attr']
            if module.value not in self.imported or attr.value not in table:
                return None
            new_module, new_attr = table[attr.value]
            attr.replace(Name(new_attr, prefix=attr.prefix))
            if new_module != module.value:
                leaves = runtime(new_module.split('.', 1)[1], module.prefix) \
                    if new_module.startswith(RUNTIME) else [Name(new_module, module.prefix)]
                first, rest = leaves[0], leaves[1:]
                module.replace(first)
                for index, trailer in enumerate(rest):
                    node.insert_child(1 + index, trailer)
            return None

        def _from_import(self, names, table):
            """``from time import clock`` -> ``from time import process_time as clock``."""
            items = names.children if names.type == syms.import_as_names else [names]
            for item in items:
                first = item.children[0] if item.type == syms.import_as_name else item
                new = table.get(first.value) if first.type == token.NAME else None
                if not new or new[0] not in ('time', 'string'):
                    continue
                if item is first:
                    first.replace(Node(syms.import_as_name, [
                        Name(new[1], prefix=first.prefix), Name('as', prefix=' '),
                        Name(first.value, prefix=' ')]))
                else:
                    first.replace(Name(new[1], prefix=first.prefix))
            return None

    class FixExp2Builtins(fixer_base.BaseFix):
        _accept_type = token.NAME
        order = 'pre'

        def start_tree(self, tree, filename):
            super().start_tree(tree, filename)
            self.bound = _bound_names(tree)

        def match(self, node):
            if node.value not in BUILTINS or node.value in self.bound:
                return False
            if not util.is_probably_builtin(node):
                return False
            parent, following = node.parent, node.next_sibling
            if parent.type == syms.argument and following is not None and \
                    following.type == token.EQUAL:
                return False                    # a keyword argument's name
            if node.value == 'round':
                return following is not None and following.type == syms.trailer and \
                    following.children[0].value == '('
            return True

        def transform(self, node, results):
            leaves = runtime(node.value, node.prefix)
            if node.parent.type == syms.power and node.parent.children[0] is node:
                parent = node.parent
                node.replace(leaves[0])
                parent.insert_child(1, leaves[1])
                return None
            return Node(syms.power, leaves)

    def _modules_imported(tree):
        """Modules the file imports under their own name (``import time``)."""
        found = set()
        for node in tree.pre_order():
            if node.type != syms.import_name:
                continue
            names = node.children[1]
            items = names.children if names.type == syms.dotted_as_names else [names]
            found.update(n.value for n in items if n.type == token.NAME)
        return found

    def _bound_names(tree):
        return {leaf.value for leaf in tree.leaves() if leaf.type == token.NAME and
                _binds(leaf)}

    def _binds(leaf):
        parent, prev = leaf.parent, leaf.prev_sibling
        if prev is not None and prev.type == token.NAME and prev.value in ('as', 'def', 'class',
                                                                           'for', 'global'):
            return True
        if parent.type in (syms.import_name, syms.import_from, syms.dotted_as_names,
                           syms.dotted_as_name, syms.import_as_names, syms.import_as_name,
                           syms.global_stmt):
            return True
        if parent.type in (syms.parameters, syms.typedargslist, syms.varargslist, syms.tname):
            return prev is None or prev.type != token.EQUAL
        if parent.type == syms.lambdef:
            return parent.children.index(leaf) < [c.type for c in parent.children].index(
                token.COLON)
        if parent.type == syms.except_clause and prev is not None and prev.type == token.COMMA:
            return True
        top = leaf
        while top.parent is not None and top.parent.type in (
                syms.exprlist, syms.testlist_star_expr, syms.testlist_gexp, syms.atom,
                syms.listmaker, syms.star_expr):
            top = top.parent
        before, following = top.prev_sibling, top.next_sibling
        if top.parent is not None and top.parent.type == syms.expr_stmt and \
                following is not None and following.type == token.EQUAL:
            return True         # an assignment's target
        return before is not None and before.type == token.NAME and before.value in ('as', 'for')

    return [FixExp2Division, FixExp2Numbers, FixExp2ModuleNames, FixExp2Builtins]

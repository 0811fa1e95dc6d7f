"""Does a file Python 3 compiles use what only Python 2 had? (No import machinery, no ROS.)

A file like ``x = raw_input("Command: ")`` or ``for k, v in d.iteritems():`` is
valid Python 3 syntax but was written for Python 2: it fails only when the line
runs. :func:`python2_names` finds such uses in a module's AST, for the names
the translation handles (2to3's fixers and exp2_py2_fixers.py):

* builtins Python 3 removed (``raw_input``, ``xrange``, ``unicode``, ...),
  loaded and bound nowhere in the file;
* methods of Python 2's dict and file (``.iteritems()``, ``.has_key()``, ...)
  and function attributes (``f.func_name``), where the file defines no such
  method or attribute itself;
* names of modules Python 3 renamed (``import Queue``, ``import urllib2``) and
  attributes Python 3 dropped (``time.clock``, ``string.letters``,
  ``sys.maxint``, ``urllib.urlencode``, ``itertools.izip``).

Code that tells the two Pythons apart is Python 3 code: what is under an
``if``/``while``/conditional expression/``and``-``or`` whose test names the
version (``sys.version_info``, ``six.PY2``, ``PY3``, ``python3``, ...), or in
the body of a ``try`` that catches NameError, ImportError or AttributeError,
is not counted. :func:`may_name_python2` is the cheap test on a compiled code
object that comes first: most files never get parsed again.
"""
import ast
import re

import exp2_py2_fixers

BUILTINS = frozenset(('raw_input', 'xrange', 'unicode', 'basestring', 'long', 'unichr',
                      'execfile', 'reduce', 'file', 'cmp', 'apply', 'buffer', 'intern',
                      'reload', 'StandardError'))
METHODS = frozenset(('iteritems', 'itervalues', 'iterkeys', 'viewitems', 'viewkeys',
                     'viewvalues', 'has_key', 'xreadlines', 'func_name', 'func_code',
                     'func_defaults', 'func_globals', 'func_closure', 'func_dict', 'func_doc',
                     'im_func', 'im_self', 'im_class'))
_URLLIB = frozenset((
    'ContentTooShortError', 'FancyURLopener', 'URLopener', 'getproxies', 'pathname2url',
    'quote', 'quote_plus', 'unquote', 'unquote_plus', 'url2pathname', 'urlcleanup',
    'urlencode', 'urlopen', 'urlretrieve'))
MODULE_ATTRIBUTES = {
    'time': frozenset(exp2_py2_fixers.MODULE_NAMES['time']),
    'string': frozenset(exp2_py2_fixers.MODULE_NAMES['string']),
    'sys': frozenset(('maxint', 'exc_type', 'exc_value', 'exc_traceback', 'exitfunc')),
    'os': frozenset(('getcwdu',)),
    'itertools': frozenset(('izip', 'imap', 'ifilter', 'izip_longest', 'ifilterfalse')),
    'urllib': _URLLIB,
}
# Python 2's modules that Python 3 renamed (2to3's fix_imports, fix_imports2, fix_urllib)
MODULES = frozenset((
    'BaseHTTPServer', 'CGIHTTPServer', 'ConfigParser', 'Cookie', 'Dialog', 'DocXMLRPCServer',
    'FileDialog', 'HTMLParser', 'Queue', 'ScrolledText', 'SimpleDialog', 'SimpleHTTPServer',
    'SimpleXMLRPCServer', 'SocketServer', 'StringIO', 'Tix', 'Tkconstants', 'Tkdnd', 'Tkinter',
    'UserList', 'UserString', '__builtin__', '_winreg', 'cPickle', 'cStringIO', 'commands',
    'cookielib', 'copy_reg', 'dbhash', 'dumbdbm', 'dummy_thread', 'gdbm', 'htmlentitydefs',
    'httplib', 'markupbase', 'robotparser', 'thread', 'tkColorChooser', 'tkCommonDialog',
    'tkFileDialog', 'tkFont', 'tkMessageBox', 'tkSimpleDialog', 'ttk', 'urlparse', 'xmlrpclib',
    'urllib2', 'whichdb', 'anydbm'))
CANDIDATES = BUILTINS | METHODS | MODULES | frozenset(
    name for names in MODULE_ATTRIBUTES.values() for name in names)
VERSION_MARK = re.compile(r'^(?:[Pp][Yy](?:thon|THON)?_?[23]\w*|[Ii][Ss]_[Pp][Yy][23]\w*|'
                          r'version_info|hexversion|version|python_version|PY[23]K?)$')
GUARD_ERRORS = frozenset(('NameError', 'ImportError', 'ModuleNotFoundError', 'AttributeError'))


def may_name_python2(code):
    """Does the code object (or one inside it) name one of the candidates? Cheap."""
    if not CANDIDATES.isdisjoint(code.co_names):
        return True
    return any(may_name_python2(c) for c in code.co_consts if hasattr(c, 'co_names'))


def _names_version(node):
    for sub in ast.walk(node):
        name = sub.id if isinstance(sub, ast.Name) else sub.attr \
            if isinstance(sub, ast.Attribute) else None
        if name is not None and VERSION_MARK.match(name):
            return True
    return False


def _catches_guard_error(handler):
    kinds = handler.type
    if kinds is None:
        return False
    elements = kinds.elts if isinstance(kinds, ast.Tuple) else [kinds]
    return any(isinstance(e, ast.Name) and e.id in GUARD_ERRORS for e in elements)


def _guarded(tree):
    """The ids of the nodes under a test of the Python version or a guarding ``try``."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.If, ast.IfExp, ast.While, ast.Assert)) and \
                _names_version(node.test):
            found.update(id(sub) for sub in ast.walk(node))
        elif isinstance(node, ast.BoolOp) and any(_names_version(v) for v in node.values):
            found.update(id(sub) for sub in ast.walk(node))
        elif isinstance(node, ast.Try) and any(_catches_guard_error(h) for h in node.handlers):
            for statement in node.body:
                found.update(id(sub) for sub in ast.walk(statement))
    return found


def _bound(tree):
    """Names the file binds anywhere, and attribute names it defines or assigns."""
    names, attributes = set(), set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
            names.add(node.id)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
            attributes.add(node.name)
        elif isinstance(node, ast.arg):
            names.add(node.arg)
        elif isinstance(node, ast.alias):
            names.add((node.asname or node.name).split('.')[0])
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            names.update(node.names)
        elif isinstance(node, ast.ExceptHandler) and node.name:
            names.add(node.name)
        elif isinstance(node, ast.Attribute) and not isinstance(node.ctx, ast.Load):
            attributes.add(node.attr)
    return names, attributes


def _modules_as_themselves(tree):
    """Modules imported under their own name (``import time``, not ``import x as time``)."""
    return {a.name for node in ast.walk(tree) if isinstance(node, ast.Import)
            for a in node.names if a.asname is None and '.' not in a.name}


def python2_names(tree):
    """What only Python 2 had that the module ``tree`` (an ``ast.Module``) uses: a sorted
    list such as ``['.iteritems()', 'raw_input', 'time.clock']``; [] for Python 3 code."""
    guarded = _guarded(tree)
    names, attributes = _bound(tree)
    modules = _modules_as_themselves(tree)
    found = set()
    for node in ast.walk(tree):
        if id(node) in guarded:
            continue
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
            if node.id in BUILTINS and node.id not in names:
                found.add(node.id)
        elif isinstance(node, ast.Attribute):
            base = node.value.id if isinstance(node.value, ast.Name) else None
            if node.attr in METHODS and node.attr not in attributes:
                found.add('.%s' % node.attr)
            elif base in MODULE_ATTRIBUTES and base in modules and \
                    node.attr in MODULE_ATTRIBUTES[base]:
                found.add('%s.%s' % (base, node.attr))
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.split('.')[0] in MODULES)
        elif isinstance(node, ast.ImportFrom) and not node.level and node.module:
            if node.module.split('.')[0] in MODULES:
                found.add(node.module)
            for alias in node.names:
                if alias.name in MODULE_ATTRIBUTES.get(node.module, ()):
                    found.add('%s.%s' % (node.module, alias.name))
    return sorted(found)


"""Imports read as Python 2 read them (installed by sitecustomize.py in the original-code shell).

``install()`` replaces the import system's finder for directories by one whose
loader for ``.py`` files is ``TabRuleLoader``. That loader changes nothing for a
file Python 3 compiles and that uses nothing only Python 2 had. Any other file
is read as Python 2 read it (exp2_py2_read.py): with Python 2's tab rule
(exp2_py2_indent.py) when Python 3 refuses its indentation, translated by
2to3's fixers when it is Python 2 code (a SyntaxError such as ``print "x"``,
or ``raw_input``, ``.iteritems()``, ...):

* the file on disk is never changed, and no bytecode of what was read is
  written to ``__pycache__``, so a later plain python3 still sees the real
  file; bytecode cached by a plain python3 for a file that names what only
  Python 2 had is not used;
* errors keep the file's name and line numbers; a file neither Python could
  read gets its error from Python's own compiler, as any import does;
* each file read this way is named on stderr (exp2_tab_report.py).

The script itself is compiled before any hook runs: python_launcher.sh starts it
through exp2_tab_script.py. One more way in is catkin's relay script (what
``catkin_install_python`` puts in a devel space, and rosrun or roslaunch
start there): it compiles the real script's text itself with ``compile()``, so
``install_for_catkin_relay`` gives that relay, and only it, a ``compile`` that
reads the same way.
"""
import importlib.machinery
import importlib.util
import os
import sys

import exp2_py2_read


def read_with_tab_rule(data, path):
    """Python 2's tab rule alone, on source bytes Python 3 refuses for their indentation.

    ``(source, code)``: the re-indented source and its code, whose columns
    point into the lines as they are in the file; ``code`` is None when
    ``source`` does not compile either (compiling it raises Python 2's error
    with the file's line). None when not needed: no tab in the indentation,
    Python 3 compiles ``data``, refuses it for something else than its
    indentation (it reports that itself), or the tab rule changes nothing.
    """
    reading = exp2_py2_read.read(data, path, python2=False)
    if reading is None or reading.how != 'tabs':
        return None
    return reading.source, reading.code


def _note(path, how, script=False):
    import exp2_tab_report
    exp2_tab_report.note(path, script=script, how=how)


class TabRuleLoader(importlib.machinery.SourceFileLoader):
    """SourceFileLoader that reads a file as Python 2 did where Python 3 cannot (exp2_py2_read).

    It acts in ``get_data``, which hands the import system the source read
    (re-indented, translated), so every failure still comes from the import
    system's own steps, with their clean tracebacks.
    """

    # Sources read as Python 2 (the tab rule, a translation): their bytecode is not cached.
    tab_rule_sources = set()

    def get_data(self, path):
        self.__dict__.pop('source_to_code', None)  # from an earlier reading of the file
        data = super().get_data(path)
        if not path.endswith(tuple(importlib.machinery.SOURCE_SUFFIXES)):
            self._check_cached(path, data)
            return data  # bytecode
        tabs, python2 = exp2_py2_read.switches()
        reading = exp2_py2_read.read(data, path, self._in_package(), tabs=tabs, python2=python2)
        if reading is None:
            return data
        if reading.code is not None:
            # get_code compiles what get_data returned: hand it the code made
            # here, whose lines and columns fit the file. (Without it, the
            # import system's compile of ``source`` gives the file's error.)
            code = reading.code
            self.source_to_code = lambda data, path, _optimize=-1: code
            if reading.how is not None:
                _note(path, reading.how)
        if reading.how is not None:
            TabRuleLoader.tab_rule_sources.add(path)
        return reading.source

    def _check_cached(self, path, data):
        """Refuse (OSError: the import system reads the source then) bytecode a plain
        python3 cached for a file that may use what only Python 2 had."""
        source = self.get_filename(self.name)
        if not exp2_py2_read.switches()[1] or exp2_py2_read.is_system_path(source):
            return
        import exp2_py2_names
        import marshal
        try:
            code = marshal.loads(data[16:])
        except (EOFError, ValueError, TypeError):
            return                      # the import system finds it bad itself
        if exp2_py2_names.may_name_python2(code):
            raise OSError('cached bytecode of %s not used: it may be Python 2' % source)

    def _in_package(self):
        return '.' in self.name or self.is_package(self.name)

    def get_source(self, fullname):
        """The file as it is on disk (for tools that show source)."""
        path = self.get_filename(fullname)
        try:
            data = super().get_data(path)
        except OSError as exc:
            raise ImportError('source not available through get_data()', name=fullname) from exc
        return importlib.util.decode_source(data)

    def set_data(self, path, data, *, _mode=0o666):
        try:
            source = importlib.util.source_from_cache(path)
        except ValueError:
            source = None
        if source in TabRuleLoader.tab_rule_sources:
            return  # a later python3 without the tab rule must see the real file
        super().set_data(path, data, _mode=_mode)


def _is_tab_rule_hook(hook):
    return getattr(hook, 'exp2_tab_rule', False)


def _is_default_file_finder_hook(hook):
    return getattr(hook, '__qualname__', '').startswith('FileFinder.path_hook.')


def install():
    """Put ``TabRuleLoader`` in the import system for every directory (idempotent)."""
    if any(_is_tab_rule_hook(hook) for hook in sys.path_hooks):
        return
    hook = importlib.machinery.FileFinder.path_hook(
        (importlib.machinery.ExtensionFileLoader, importlib.machinery.EXTENSION_SUFFIXES),
        (TabRuleLoader, importlib.machinery.SOURCE_SUFFIXES),
        (importlib.machinery.SourcelessFileLoader, importlib.machinery.BYTECODE_SUFFIXES))
    hook.exp2_tab_rule = True
    for index, existing in enumerate(sys.path_hooks):
        if _is_default_file_finder_hook(existing):
            sys.path_hooks[index] = hook
            break
    else:
        sys.path_hooks.append(hook)
    # Finders made before now (site, this module's own directory) use the old loader.
    sys.path_importer_cache.clear()


# The header of catkin's relay scripts (catkin/cmake/templates/script.py.in).
CATKIN_RELAY = b'# generated from catkin/cmake/template/script.py.in'


def tab_rule_compile(source, filename, mode, flags=0, dont_inherit=False, optimize=-1):
    """``compile()``, but the file ``filename`` is read as Python 2 did where Python 3 cannot."""
    tabs, python2 = exp2_py2_read.switches()
    if mode != 'exec' or not os.path.isfile(filename) or not (tabs or python2):
        return compile(source, filename, mode, flags, dont_inherit, optimize)
    with open(filename, 'rb') as script:
        reading = exp2_py2_read.read(script.read(), filename, optimize=optimize, tabs=tabs,
                                     python2=python2)
    if reading is None or reading.how is None:
        return compile(source, filename, mode, flags, dont_inherit, optimize)
    if reading.code is None:  # raises the file's error, on its line
        compile(reading.source, filename, 'exec', dont_inherit=True)
        return compile(source, filename, mode, flags, dont_inherit, optimize)
    _note(filename, reading.how, script=True)
    return reading.code


def install_for_catkin_relay(main_module, argv):
    """If the program is a catkin relay script, give it ``tab_rule_compile`` as ``compile``.

    Called at start-up, before the interpreter runs the script in
    ``main_module``'s namespace; the real script runs in a namespace of its
    own, with the real builtins.
    """
    path = argv[0] if argv else ''
    if not os.path.isfile(path):  # -c, -m, a directory; never read a pipe (python3 <(...))
        return
    try:
        with open(path, 'rb') as script:
            head = script.read(512)
    except OSError:
        return
    if CATKIN_RELAY in head:
        main_module.__dict__['compile'] = tab_rule_compile

"""Runs a script as ``python3 SCRIPT ARGS`` would, read as Python 2 did where Python 3 cannot.

The interpreter compiles its script before any start-up hook could help, so
the ``python`` and ``python3`` of the original-code shell
(src/exp_assignment2/original_env/programs/python_launcher.sh) start a script as

    /usr/bin/python3 [OPTIONS] -c 'import exp2_tab_script; exp2_tab_script.main()' SCRIPT ARGS

and ``main`` does what the interpreter does for ``SCRIPT ARGS``: sys.argv,
sys.orig_argv, sys.path[0] (the script's real directory, unless -P or -I),
a fresh ``__main__`` with the same attributes, and tracebacks without this
runner's frames. Only the compile step differs: a script Python 3 refuses, or
that uses what only Python 2 had, is compiled as Python 2 read it
(exp2_py2_read.py: the tab rule, the translation). A script Python 3 accepts
is compiled from its bytes, exactly as it is. A file that is not Python source
(a zip application, bytecode) goes to the interpreter as it was given.
"""
import builtins
import importlib.machinery
import importlib.util
import os
import sys

import exp2_py2_read
import exp2_tab_import


def _hide_runner_frames(hook):
    """An excepthook that drops this runner's frames from the start of a traceback."""
    own = os.path.abspath(__file__)

    def excepthook(exc_type, value, tb):
        while tb is not None and tb.tb_frame.f_code.co_filename in (own, '<string>'):
            tb = tb.tb_next
        if isinstance(value, BaseException):
            value.__traceback__ = tb  # Python prints the exception's own traceback
        hook(exc_type, value, tb)
    return excepthook


def _drop_runner_arguments(argv):
    """``argv`` (sys.orig_argv) without the ``-c CODE`` that started this runner."""
    for index in range(1, len(argv) - 1):
        if argv[index] == '-c' and 'exp2_tab_script' in argv[index + 1]:
            return argv[:index] + argv[index + 2:]
    return argv


def main():
    """Run sys.argv[1] (sys.argv == ['-c', SCRIPT, ARGS...]) as the program's __main__."""
    del sys.argv[0]
    if hasattr(sys, 'orig_argv'):
        sys.orig_argv[:] = _drop_runner_arguments(sys.orig_argv)
    path = sys.argv[0]
    filename = path if os.path.isabs(path) else os.path.join(os.getcwd(), path)
    if not (getattr(sys.flags, 'safe_path', False) or sys.flags.isolated):
        sys.path[0] = os.path.dirname(os.path.realpath(path))  # -c put '' there
    sys.excepthook = _hide_runner_frames(sys.excepthook)
    exp2_tab_import.install()  # also under -S, which skips sitecustomize
    with open(path, 'rb') as script:
        data = script.read()
    if data.startswith(b'PK\x03\x04') or importlib.util.MAGIC_NUMBER == data[:4]:
        argv = _drop_runner_arguments(list(getattr(sys, 'orig_argv', [sys.executable] + sys.argv)))
        os.execv(sys.executable, [sys.executable] + argv[1:])
    tabs, python2 = exp2_py2_read.switches()
    reading = exp2_py2_read.read(data, filename, tabs=tabs, python2=python2)
    if reading is None:
        code = compile(data, filename, 'exec', dont_inherit=True)
    elif reading.code is None:  # raises the error of the file, on its line
        code = compile(reading.source, filename, 'exec', dont_inherit=True)
    else:
        code = reading.code
        if reading.how is not None:
            import exp2_tab_report
            exp2_tab_report.note(filename, script=True, how=reading.how)
    namespace = sys.modules['__main__'].__dict__
    namespace.clear()
    namespace.update(__name__='__main__', __doc__=None, __package__=None,
                     __loader__=importlib.machinery.SourceFileLoader('__main__', filename),
                     __spec__=None, __annotations__={}, __builtins__=builtins,
                     __file__=filename, __cached__=None)
    exp2_tab_import.install_for_catkin_relay(sys.modules['__main__'], [path])
    exec(code, namespace)

"""Tracebacks without the frames of this environment's run-time helpers.

Code read as Python 2 calls exp2_py2_runtime (``7 / 0`` is ``_exp2_py2.div(7, 0)``)
and ``input()`` reaches exp2_keyboard: an error or a Ctrl-C there would show
their frames last, below the student's line, where Python 2 showed the
student's line. :func:`hide` leaves a file's frames out of what
``sys.excepthook`` (an uncaught error), ``threading.excepthook`` (a thread's)
and the ``traceback`` module (rospy's callback errors, ``print_exc``) print.
"""
import sys
import threading
import traceback

_files = {}     # file name -> its frames end the traceback (what they called is hidden too)


def _hidden(tb):
    return tb.tb_frame.f_code.co_filename in _files


def _kept(tb):
    """The chain of traceback entries from ``tb`` on, with the hidden files' unlinked."""
    while tb is not None and _hidden(tb):
        if _files[tb.tb_frame.f_code.co_filename]:
            return None
        tb = tb.tb_next
    first = tb
    while tb is not None:
        while tb.tb_next is not None and _hidden(tb.tb_next):
            if _files[tb.tb_next.tb_frame.f_code.co_filename]:
                tb.tb_next = None
                break
            tb.tb_next = tb.tb_next.tb_next
        tb = tb.tb_next
    return first


def without_hidden(exc, seen=None):
    """``exc`` (and its cause and context) with the hidden files' frames unlinked."""
    seen = set() if seen is None else seen
    if isinstance(exc, BaseException) and id(exc) not in seen:
        seen.add(id(exc))
        exc.__traceback__ = _kept(exc.__traceback__)
        without_hidden(exc.__cause__, seen)
        without_hidden(exc.__context__, seen)
    return exc


def _excepthook(hook):
    def excepthook(exc_type, value, tb):
        if isinstance(value, BaseException):
            tb = without_hidden(value.with_traceback(tb)).__traceback__
        return hook(exc_type, value, tb)
    return excepthook


def _thread_hook(hook):
    def excepthook(args):
        without_hidden(args.exc_value)
        return hook(args)
    return excepthook


def _walk(walk):
    def walk_without_hidden(tb, *args, **kwargs):
        for item in walk(tb, *args, **kwargs):
            name = item[0].f_code.co_filename
            if name in _files and _files[name]:
                return
            if name not in _files:
                yield item
    return walk_without_hidden


def hide(filename, and_below=False):
    """Leave the frames of code from ``filename`` out of tracebacks (the hooks: once);
    ``and_below``: the frames of what it called too (the interpreter's own waits)."""
    if not _files:
        sys.excepthook = _excepthook(sys.excepthook)
        threading.excepthook = _thread_hook(threading.excepthook)
        for name in ('walk_tb', '_walk_tb_with_full_positions'):
            if hasattr(traceback, name):
                setattr(traceback, name, _walk(getattr(traceback, name)))
    _files[filename] = and_below

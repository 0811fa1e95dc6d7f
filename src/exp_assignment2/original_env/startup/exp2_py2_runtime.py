"""What code read as Python 2 calls at run time: ``_exp2_py2`` in its builtins.

The translation (exp2_py2_translate.py) rewrites what 2to3 leaves with Python
3's meaning where Python 2's differed, into calls of this module, reached
through one builtin name (``install``) so that no line is added to the file:

* ``div(a, b)``, ``idiv(a, b)``: ``/`` and ``/=`` as Python 2 computed them
  without ``from __future__ import division``: two integers (int, bool,
  numpy's integer scalars and integer arrays) floor, anything else divides
  truly (a class of Python 2 with only ``__div__`` gets it called);
* ``round``: Python 2's, half away from zero, always a float;
* ``cmp``, ``file``: builtins Python 3 removed (``file(...)`` opens a file,
  ``isinstance(x, file)`` is true for any file object);
* ``string``: the functions of Python 2's ``string`` module that Python 3
  dropped (``string.join(words, sep)``, ``string.atoi``, ``string.split``, ...);
* ``import_star``: ``from module import *`` in a function (exp2_py2_lenient.py).

A traceback through these functions (``7 / 0``) shows the student's line
last, as Python 2's did (exp2_hidden_frames.py).
"""
import builtins
import decimal
import importlib
import io
import numbers
import sys
import types

NAME = '_exp2_py2'


def _integral(value):
    if type(value) is int or isinstance(value, numbers.Integral):
        return True
    dtype = getattr(value, 'dtype', None)       # numpy arrays: Python 2's numpy floored too
    return getattr(dtype, 'kind', None) in ('i', 'u', 'b') and hasattr(value, 'shape')


def _classic(a, b, name, reflected):
    """``a.__div__(b)`` or ``b.__rdiv__(a)`` of a class written for Python 2, else None."""
    for obj, other, method in ((a, b, name), (b, a, reflected)):
        impl = getattr(type(obj), method, None)
        if impl is not None:
            result = impl(obj, other)
            if result is not NotImplemented:
                return result
    return None


def div(a, b):
    """``a / b`` as Python 2 computed it."""
    if _integral(a) and _integral(b):
        return a // b
    try:
        return a / b
    except TypeError:
        result = _classic(a, b, '__div__', '__rdiv__')
        if result is None:
            raise
        return result


def idiv(a, b):
    """``a /= b`` as Python 2 computed it: the value to bind to the target."""
    if _integral(a) and _integral(b):
        a //= b
        return a
    try:
        a /= b
    except TypeError:
        result = _classic(a, b, '__idiv__', '__rdiv__')
        if result is None:
            result = _classic(a, b, '__div__', '__rdiv__')
        if result is None:
            raise
        return result
    return a


def round(number, ndigits=0):  # noqa: A001 (Python 2's builtin, by its name)
    """Python 2's ``round``: a float, halves rounded away from zero."""
    if not isinstance(number, numbers.Real):
        return builtins.round(number, ndigits)
    value = float(number)
    if value != value or value in (float('inf'), float('-inf')):
        return value
    try:
        exact = decimal.Decimal(value)          # the binary value, as Python 2 rounded it
        step = decimal.Decimal(1).scaleb(-int(ndigits))
        return float(exact.quantize(step, rounding=decimal.ROUND_HALF_UP))
    except decimal.InvalidOperation:            # more digits than the value has
        return value


def cmp(a, b):
    """Python 2's ``cmp``: -1, 0 or 1."""
    return (a > b) - (a < b)


class _FileType(type):
    def __instancecheck__(cls, obj):
        return isinstance(obj, io.IOBase)


class file(metaclass=_FileType):  # noqa: N801 (Python 2's builtin, by its name)
    """Python 2's ``file``: calling it opens a file."""

    def __new__(cls, name, mode='r', buffering=-1):
        return open(name, mode, buffering)


def _join(words, sep=' '):
    return sep.join(words)


def _zfill(x, width):
    return (x if isinstance(x, str) else repr(x)).zfill(width)


string = types.SimpleNamespace(
    atoi=lambda s, base=10: int(s, base), atol=lambda s, base=10: int(s, base),
    atof=float, capitalize=str.capitalize, expandtabs=str.expandtabs, find=str.find,
    rfind=str.rfind, index=str.index, rindex=str.rindex, count=str.count, lower=str.lower,
    upper=str.upper, swapcase=str.swapcase, strip=str.strip, lstrip=str.lstrip,
    rstrip=str.rstrip, split=str.split, splitfields=str.split, rsplit=str.rsplit,
    replace=str.replace, ljust=str.ljust, rjust=str.rjust, center=str.center,
    join=_join, joinfields=_join, zfill=_zfill)


def import_star(module, level):
    """``from module import *`` (``level`` dots before it) run in a function, as
    Python 2 ran it: the module's public names (its ``__all__``, else those
    without a leading underscore) bound when the line runs, in the caller's
    module globals, where the function finds them."""
    caller = sys._getframe(1).f_globals
    if level:
        package = caller.get('__package__') or caller['__name__'].rpartition('.')[0]
        found = importlib.import_module('.' * level + module, package)
    else:
        found = importlib.import_module(module)
    names = getattr(found, '__all__', None)
    if names is None:
        names = [name for name in vars(found) if not name.startswith('_')]
    caller.update((name, getattr(found, name)) for name in names)


def install():
    """Make this module the builtin ``_exp2_py2``, its frames left out of tracebacks
    (idempotent)."""
    import exp2_hidden_frames
    setattr(builtins, NAME, sys.modules[__name__])
    exp2_hidden_frames.hide(__file__)

"""Python 2 code read by the original-code environment, as plain functions (no subprocess).

src/exp_assignment2/original_env/startup: exp2_py2_read.read (when it translates, what the
code then does, on which lines), exp2_py2_translate (2to3's fixers and ours, line by
line), exp2_py2_names (what makes a file Python 3 compiles Python 2 code).
"""
import io
import textwrap
import traceback

import pytest

from py2_helpers import read, run

import exp2_py2_translate  # noqa: E402  (on the path py2_helpers gives)


def test_print_statements_as_python2_printed():
    _, out = run('''
        import sys
        print "Reached", 1
        print "a",
        print "b"
        print >>sys.stdout, "to", "file"
        print
        print("x", 2)
        ''')
    assert out == "Reached 1\na b\nto file\n\n('x', 2)\n"


def test_except_raise_octal_backquotes_and_the_rest_of_the_syntax():
    namespace, out = run('''
        try:
            raise ValueError, "msg"
        except ValueError, e:
            caught = str(e)
        mode = 0777
        big = 10L + 0777L
        shown = `mode`
        different = 1 <> 2
        exec "x = 5"
        ''')
    assert (namespace['caught'], namespace['mode'], namespace['big'], namespace['shown'],
            namespace['different'], namespace['x']) == ('msg', 511, 521, '511', True, 5)
    assert namespace['__builtins__'] is not None and out == ''


def test_python2_names_and_lists():
    namespace, _ = run('''
        import time, string
        d = {'a': 1}
        keys = d.keys()
        first = d.keys()[0]
        pairs = [(k, v) for k, v in d.iteritems()]
        has = d.has_key('a')
        doubled = map(lambda v: v * 2, [1, 2])
        odd = filter(lambda v: v % 2, [1, 2, 3])
        zipped = zip([1, 2], 'ab')
        count = len(xrange(4))
        text = unicode('u') + unichr(65)
        ints = isinstance(3L, (int, long)) and isinstance('s', basestring)
        total = reduce(lambda a, b: a + b, [1, 2, 3])
        cpu = time.clock()
        letters = string.letters[:3] + string.join(['x', 'y'], '-') + str(string.atoi('12'))
        order = cmp(1, 2), cmp(2, 2)
        rounded = round(2.5), round(-0.5), round(2.675, 2)
        ''')
    assert namespace['keys'] == ['a'] and namespace['first'] == 'a'
    assert namespace['pairs'] == [('a', 1)] and namespace['has'] is True
    assert (namespace['doubled'], namespace['odd'], namespace['zipped']) == (
        [2, 4], [1, 3], [(1, 'a'), (2, 'b')])
    assert (namespace['count'], namespace['text'], namespace['ints'], namespace['total']) == (
        4, 'uA', True, 6)
    assert isinstance(namespace['cpu'], float)
    assert namespace['letters'] == 'abcx-y12'
    assert namespace['order'] == (-1, 0)
    assert namespace['rounded'] == (3.0, -1.0, 2.67)     # Python 2's: away from zero, a float


def test_raw_input_and_input_as_python2_read_them():
    namespace, out = run('''
        name = raw_input("Name: ")
        value = input("Value: ")
        ''', stdin='rex\n3 * 4\n')
    assert (namespace['name'], namespace['value']) == ('rex', 12)  # input() evaluated it
    assert out == 'Name: Value: '


def test_integer_division_as_python2():
    namespace, _ = run('''
        print "Python 2 code"
        import numpy
        a, b = 7, 2
        ints = a / b, 7 / 2, -7 / 2, True / 2
        floats = 7.0 / 2, a / 2.0, a / float(b)
        numpy_ints = numpy.int64(7) / 2, list(numpy.array([7, 9]) / 2)
        numpy_floats = list(numpy.array([7.0]) / 2)
        x = 9
        x /= 2
        y = [9.0]
        y[0] /= 2
        mixed = a / b * 2.0
        ''')
    assert namespace['ints'] == (3, 3, -4, 0)
    assert namespace['floats'] == (3.5, 3.5, 3.5)
    assert namespace['numpy_ints'] == (3, [3, 4])
    assert namespace['numpy_floats'] == [3.5]
    assert (namespace['x'], namespace['y'], namespace['mixed']) == (4, [4.5], 6.0)
    namespace, _ = run('''
        from __future__ import division
        print "future"
        half = 7 / 2
        ''')
    assert namespace['half'] == 3.5


def test_a_class_of_python2_divides_with_its_div():
    namespace, _ = run('''
        class Money(object):
            def __init__(self, cents):
                self.cents = cents
            def __div__(self, n):
                return Money(self.cents / n)
        print "x"
        share = (Money(7) / 2).cents
        ''')
    assert namespace['share'] == 3


def test_tabs_and_python2_together_on_one_file():
    source = b'def f(n):\n\tif n:\n\t    print "n", n / 2\n        return n\nf(7)\n'
    reading = read(source)
    assert reading.how == 'python2'
    _, out = run(source)
    assert out == 'n 3\n'


def test_a_traceback_shows_the_students_lines():
    source = textwrap.dedent('''\
        """Lines 1 to 3: a docstring, an import 2to3 splits in two."""
        from urllib import urlencode, quote
        import sys
        try:
            raise ValueError(1, 2)
        except ValueError, (a, b):
            print >>sys.stderr, "caught", a, b
        def fail((x, y)):
        \tif x:
        \t    return reduce(lambda p, q: p + q, [x, y]) / 0
        fail((1, 2))
        ''')
    translation = exp2_py2_translate.translate(source)
    assert len(translation.text.splitlines()) > len(source.splitlines())   # lines were added
    with pytest.raises(ZeroDivisionError) as error:
        run(source)
    frames = [(f.name, f.lineno) for f in traceback.extract_tb(error.value.__traceback__)
              if f.filename.endswith('node.py')]
    assert frames == [('<module>', 11), ('fail', 10)]


def test_every_line_of_the_translation_knows_its_line():
    source = 'import sys\nfrom urllib import urlencode, quote\nx = reduce(max, [1])\n' \
             'print "a", \\\n   7 / 2\n"""two\nlines"""\n'
    translation = exp2_py2_translate.translate(source)
    lines = translation.text.split('\n')
    origins = dict(zip(lines, translation.lines))
    assert origins['import sys'] == 1
    assert origins['from urllib.parse import urlencode, quote'] == 2
    assert origins['x = reduce(max, [1])'] == 3
    assert origins['"""two'] == 6 and origins['lines"""'] == 7
    assert None in translation.lines            # 'from functools import reduce', made up
    assert [o for o in translation.lines if o is not None] == sorted(
        o for o in translation.lines if o is not None)


def test_a_translation_that_does_not_compile_fails_on_the_files_line():
    reading = read('import sys\nprint "a"\n\n\ndef f(a, a):\n    pass\n')
    assert reading.code is None
    with pytest.raises(SyntaxError) as error:
        compile(reading.source, 'node.py', 'exec')
    assert (error.value.lineno, error.value.msg) == (
        5, "duplicate argument 'a' in function definition")


def test_neither_python_reads_it_python3_says_why():
    assert read('def f(:\n    pass\n') is None     # Python 3's own error, from its compiler


@pytest.mark.parametrize('source', [
    'print("x", 7 / 2)\n',
    'def raw_input(prompt):\n    return "mine"\nprint(raw_input("x"))\n',
    'import sys\nif sys.version_info[0] < 3:\n    text = raw_input()\nelse:\n    text = input()\n',
    'try:\n    unicode\nexcept NameError:\n    unicode = str\n',
    'try:\n    from Queue import Queue\nexcept ImportError:\n    from queue import Queue\n',
    'import six\nif six.PY2:\n    items = d.iteritems()\n',
    'class D(dict):\n    def has_key(self, k):\n        return k in self\nD().has_key(1)\n',
    'x = python3 or type(v) == unicode\n',
])
def test_python3_code_runs_untouched(source):
    reading = read(source)
    assert reading.how is None and reading.source == source.encode()
    assert reading.code.co_code == compile(source, 'node.py', 'exec').co_code


@pytest.mark.parametrize('source,what', [
    ('x = raw_input("Command: ")\n', 'raw_input'),
    ('for k, v in d.iteritems():\n    pass\n', '.iteritems'),
    ('if d.has_key(1):\n    pass\n', '.has_key'),
    ('import time\nt = time.clock()\n', 'time.clock'),
    ('import string\ns = string.letters\n', 'string.letters'),
    ('import Queue\n', 'Queue'),
    ('for i in xrange(3):\n    pass\n', 'xrange'),
])
def test_python3_syntax_with_python2_names_is_translated(source, what):
    import ast
    import exp2_py2_names
    assert any(what in name for name in exp2_py2_names.python2_names(ast.parse(source)))
    assert read(source).how == 'python2'


def test_the_interpreters_own_libraries_are_never_translated():
    source = b'x = unicode("a")\n'
    assert read(source, '/usr/lib/python3/dist-packages/genpy/message.py').how is None
    assert read(source).how == 'python2'


def test_the_runtime_reads_as_python2():
    import exp2_py2_runtime as runtime
    assert runtime.div(7, 2) == 3 and runtime.div(-7, 2) == -4 and runtime.div(7.0, 2) == 3.5
    value = [1]
    assert runtime.idiv(value and 9, 2) == 4
    assert runtime.round(0.5) == 1.0 and runtime.round(1.5) == 2.0 and runtime.round(-2.5) == -3.0
    assert runtime.round(float('inf')) == float('inf')
    assert runtime.cmp('a', 'b') == -1 and runtime.cmp(3, 1) == 1
    assert isinstance(io.StringIO(), runtime.file) and not isinstance('x', runtime.file)
    assert runtime.string.join(['a', 'b']) == 'a b' and runtime.string.zfill(7, 3) == '007'
    with pytest.raises(ZeroDivisionError):
        runtime.div(1, 0)

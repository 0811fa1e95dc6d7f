"""What Python 2.7 compiled with a warning and Python 3 refuses runs as on Python 2
(exp2_py2_lenient.py), on the student's lines, with Python 2's warnings; a case each.
As plain functions; test_py2_runs.py starts real interpreters."""
import traceback
import warnings

import pytest

from py2_helpers import NODE, read, run


def warned(source):
    """(namespace, printed, [(warning, line)]) of ``source`` read and run."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        namespace, out = run(source)
    said = [(str(w.message), w.lineno) for w in caught
            if issubclass(w.category, SyntaxWarning) and w.filename == NODE]
    return namespace, out, said


# Lines 2 and 3: 2to3 adds a line (from functools import reduce) before the file's line 4.
COUNTER = '''\
import rospy_free_counter_node
from urllib import urlencode, quote
total = reduce(lambda a, b: a + b, [0])
count = 0
def callback(msg):
    count = count + msg
    global count
    if count > 3:
        raise ValueError("too many: %d" % count)
    print "count", count
'''


def test_a_global_after_its_assignment_is_the_whole_functions(tmp_path, monkeypatch):
    (tmp_path / 'rospy_free_counter_node.py').write_text('')
    monkeypatch.syspath_prepend(str(tmp_path))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        reading = read(COUNTER)
    assert reading.how == 'python2'
    assert [(str(w.message), w.lineno) for w in caught if w.filename == NODE] == [
        ("name 'count' is assigned to before global declaration", 7)]
    namespace = {'__name__': '__main__'}
    exec(reading.code, namespace)
    namespace['callback'](2)
    assert namespace['count'] == 2
    with pytest.raises(ValueError) as error:
        namespace['callback'](2)
    frames = [(f.name, f.lineno) for f in traceback.extract_tb(error.value.__traceback__)
              if f.filename == NODE]
    assert frames == [('callback', 9)]          # the student's line, not the translation's


def test_a_global_after_its_use_in_a_nested_block_of_a_method():
    namespace, out, said = warned('''
        speed = 1.0
        class Follower(object):
            def on_image(self, radius):
                """The docstring stays the docstring."""
                if radius > 10:
                    print "seen at", speed
                    if radius > 50:
                        global speed
                        speed = 0.5
                return speed
        f = Follower()
        first = f.on_image(20)
        print first, f.on_image(60), speed
        ''')
    assert out == 'seen at 1.0\nseen at 1.0\n1.0 0.5 0.5\n'
    assert said == [("name 'speed' is used prior to global declaration", 9)]
    assert namespace['Follower'].on_image.__doc__ == 'The docstring stays the docstring.'


def test_globals_late_in_several_functions_and_at_module_level():
    namespace, out, said = warned('''
        from __future__ import print_function
        state = "NORMAL"
        global state
        def sleep():
            state = "SLEEP"
            global state, home
            home = (7, 7)
        def play():
            print(state)
            global state
            state = "PLAY"
        sleep()
        play()
        print(state, home)
        ''')
    assert out == "SLEEP\nPLAY (7, 7)\n"
    assert said == [("name 'state' is assigned to before global declaration", 4),
                    ("name 'state' is assigned to before global declaration", 7),
                    ("name 'state' is used prior to global declaration", 11)]


def test_a_global_of_a_parameter_stays_an_error_as_in_python2():
    reading = read('print "x"\ndef f(x):\n    x = 1\n    global x\n')
    assert reading.code is None
    with pytest.raises(SyntaxError) as error:
        compile(reading.source, NODE, 'exec')
    assert error.value.lineno == 4


def test_import_star_in_a_function_binds_the_names_when_it_runs():
    namespace, out, said = warned('''
        def distance(a, b):
            from math import *
            return sqrt((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2)

        def nothing_yet():
            return "sqrt" in globals()
        print nothing_yet()
        print distance((0, 0), (3, 4)), nothing_yet()
        ''')
    assert out == 'False\n5.0 True\n'
    assert said == [('import * only allowed at module level', 2)]   # the def's line, as 2.7


def test_import_star_in_a_function_of_a_package_module(tmp_path, monkeypatch):
    package = tmp_path / 'studentpkg'
    package.mkdir()
    (package / '__init__.py').write_text('')
    (package / 'helper.py').write_text('__all__ = ["HOME"]\nHOME = (7, 7)\nHIDDEN = 1\n')
    monkeypatch.syspath_prepend(str(tmp_path))
    import exp2_py2_read
    source = b'def home():\n    from helper import *\n    return HOME, "HIDDEN" in globals()\n'
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        reading = exp2_py2_read.read(source, str(package / 'node.py'), in_package=True)
    assert [(str(w.message), w.lineno) for w in caught] == [
        ('import * only allowed at module level', 1)]
    namespace = {'__name__': 'studentpkg.node', '__package__': 'studentpkg'}
    exec(reading.code, namespace)
    assert namespace['home']() == ((7, 7), False)


def test_async_and_await_as_names_are_renamed_alike_everywhere():
    namespace, out, said = warned('''
        class Client(object):
            def __init__(self, async=False):
                self.async = async
            def send(self, goal, await=None):
                return (goal, self.async, await)
        print Client(async=True).send(1, await=2)
        ''')
    assert out == '(1, True, 2)\n' and said == []
    assert read('def f(x):\n    return x\n').how is None    # Python 3 code: untouched

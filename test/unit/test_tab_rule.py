"""Python 2's tab rule of the original-code shell, as plain functions (no subprocess).

src/exp_assignment2/original_env/startup: exp2_py2_indent (the re-indenter), exp2_tab_import's
read_with_tab_rule (when it acts), exp2_code_columns (columns of tracebacks),
exp2_tab_report's idea of an import statement. The fixtures in
test/original_tabs mix tabs and spaces as original student code does.
"""
import ast
import os
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STARTUP = os.path.join(REPO, 'src', 'exp_assignment2', 'original_env', 'startup')
FIXTURES = os.path.join(REPO, 'test', 'original_tabs')
sys.path.insert(0, STARTUP)

import exp2_code_columns  # noqa: E402
import exp2_py2_indent  # noqa: E402
import exp2_tab_import  # noqa: E402
import exp2_tab_report  # noqa: E402


def fixture(name):
    with open(os.path.join(FIXTURES, name), 'rb') as f:
        return f.read()


def run_module(source, name):
    namespace = {'__name__': name}
    exec(compile(source, name + '.py', 'exec'), namespace)
    return namespace


def test_columns_as_python2_counted_them():
    column = exp2_py2_indent.python2_column
    assert column('\t') == 8
    assert column('    \t') == 8       # spaces then a tab: still the next multiple of 8
    assert column('\t    ') == 12
    assert column('        \t') == 16
    assert column(' \t \t') == 16
    assert column('\t\f  ') == 2       # a form feed starts again at 0
    assert column('  ') == 2


def test_only_the_indentation_of_logical_lines_changes():
    text = '\n'.join([
        'def f(a):',                       # 1
        '\tif a:',                          # 2: tab -> 8
        '\t    x = "a\\tb\t c"',             # 3: tab + 4 -> 12; tabs in the string stay
        '\t    y = """one',                  # 4: a string that goes on
        '\ttwo, in the string',             # 5: inside the string: stays
        '        three"""',                  # 6: inside the string: stays
        '\t    z = (1,',                     # 7
        '\t\t 2)',                           # 8: inside brackets: stays
        '\t    w = 1 + \\',                  # 9
        '\t\t\t2',                           # 10: after a backslash: stays
        '\t# a comment',                     # 11: comment-only: stays
        '\t',                                # 12: blank: stays
        "\t    v = 'it\\",                   # 13: a one-line string with an escaped newline
        "\tgoes on'",                        # 14: still in the string: stays
        '        return x, y, z, w, v',      # 15: spaces: stays
    ])
    fixed, shifts = exp2_py2_indent.python2_indentation(text)
    lines = fixed.split('\n')
    assert len(lines) == 15
    assert lines[1] == ' ' * 8 + 'if a:'
    assert lines[2] == ' ' * 12 + 'x = "a\\tb\t c"'
    assert lines[3] == ' ' * 12 + 'y = """one'
    assert lines[6] == ' ' * 12 + 'z = (1,'
    assert lines[8] == ' ' * 12 + 'w = 1 + \\'
    assert lines[12] == ' ' * 12 + "v = 'it\\"
    unchanged = [5, 6, 8, 10, 11, 12, 14, 15]
    assert [lines[n - 1] for n in unchanged] == [text.split('\n')[n - 1] for n in unchanged]
    assert shifts == {2: 1 - 8, 3: 5 - 12, 4: 5 - 12, 7: 5 - 12, 9: 5 - 12, 13: 5 - 12}
    namespace = run_module(fixed, 'snippet')
    assert namespace['f'](True) == ('a\tb\t c', 'one\n\ttwo, in the string\n        three',
                                    (1, 2), 3, 'it\tgoes on')


def test_the_fixtures_mean_what_python2_meant():
    node, helper = fixture('tabs_node.py'), fixture('tabs_helper.py')
    for source in (node, helper):  # what they are about: Python 3 refuses them
        with pytest.raises(TabError):
            compile(source, 'fixture.py', 'exec')
    helper_source, _ = exp2_py2_indent.python2_source(helper)
    helper_module = run_module(helper_source, 'tabs_helper')
    # tab = 8 columns puts "seen += 100" inside the loop (4 columns: after it)
    assert helper_module['tally'](['a', 'b']) == 202
    separator, second_line, total = helper_module['strings']()
    assert separator == 'a\tb'
    assert second_line == '\tsecond line, after a tab in the string'
    sys.modules['tabs_helper'] = type(sys)('tabs_helper')
    try:
        sys.modules['tabs_helper'].__dict__.update(helper_module)
        node_module = run_module(exp2_py2_indent.python2_source(node)[0], 'tabs_node')
    finally:
        del sys.modules['tabs_helper']
    assert node_module['count'](3) == 33


def test_what_python3_reads_is_left_alone():
    assert exp2_tab_import.read_with_tab_rule(b'def f():\n\treturn 1\n', 'tabs_only.py') is None
    assert exp2_tab_import.read_with_tab_rule(b'def f():\n    return 1\n', 'spaces.py') is None
    assert exp2_tab_import.read_with_tab_rule(b'x = "\t"\n', 'string_tab.py') is None
    # refused for another reason: Python 3 reports it, not the tab rule
    assert exp2_tab_import.read_with_tab_rule(b'if 1:\n\tprint "x"\n', 'py2_print.py') is None
    source, code = exp2_tab_import.read_with_tab_rule(fixture('tabs_helper.py'), 'tabs_helper.py')
    assert source.count(b'\n') == fixture('tabs_helper.py').count(b'\n')
    assert code.co_filename == 'tabs_helper.py'


@pytest.mark.parametrize('source,line,message', [
    (b'def f():\n        x = 1\n\tif x:\n\t\ty = 2\n    return 3\n', 5,
     'unindent does not match any outer indentation level'),
    (b'x = 1\n\ty = 2\nz = 3\n', 2, 'unexpected indent'),
    (b'if True:\n\tx = 1\n        y = 2\n\t\t  z = 3\n', 4, 'unexpected indent'),
])
def test_what_python2_could_not_indent_gets_its_error_on_the_real_line(source, line, message):
    fixed, code = exp2_tab_import.read_with_tab_rule(source, 'bad.py')
    assert code is None
    with pytest.raises(IndentationError) as error:
        compile(fixed, 'bad.py', 'exec')
    assert (error.value.filename, error.value.lineno, error.value.msg) == ('bad.py', line, message)
    assert not isinstance(error.value, TabError)


def test_encoding_line_ends_and_bom_are_kept():
    latin = '# -*- coding: latin-1 -*-\nif 1:\n\tx = "caf\xe9"\n        y = x\n'.encode('latin-1')
    assert run_module(exp2_py2_indent.python2_source(latin)[0], 'latin')['y'] == 'caf\xe9'
    crlf = b'if 1:\r\n\tx = 1\r\n        y = x + 1\r\n'
    fixed, shifts = exp2_py2_indent.python2_source(crlf)
    assert run_module(fixed, 'crlf')['y'] == 2 and sorted(shifts) == [2]
    bom = b'\xef\xbb\xbfif 1:\n\tx = "\xc3\xa9"\n        y = x\n'
    fixed, _ = exp2_py2_indent.python2_source(bom)
    assert fixed.startswith(b'\xef\xbb\xbf') and run_module(fixed, 'bom')['y'] == '\xe9'
    assert exp2_py2_indent.python2_source(b'if 1:\n    x = 1\n') is None


def test_the_cheap_test_for_tabs_in_indentation():
    assert exp2_py2_indent.has_tab_indentation(b'if 1:\n  \tx = 1\n')
    assert exp2_py2_indent.has_tab_indentation(b'\fif 1:\n\f\tx = 1\n')
    assert not exp2_py2_indent.has_tab_indentation(b'x = "\t"\ny = 1  \t# c\n')


needs_columns = pytest.mark.skipif(sys.version_info < (3, 11),
                                   reason='code objects have columns since Python 3.11')


def positions_of(code, line):
    """The (start, end) columns of every instruction of ``code`` (nested too) on ``line``."""
    found = set()
    for start_line, end_line, col, end_col in code.co_positions():
        if start_line == end_line == line and col is not None:
            found.add((col, end_col))
    for const in code.co_consts:
        if hasattr(const, 'co_code'):
            found |= positions_of(const, line)
    return found


@needs_columns
def test_columns_point_into_the_line_as_it_is_in_the_file():
    data = fixture('tabs_helper.py')
    _, code = exp2_tab_import.read_with_tab_rule(data, 'tabs_helper.py')
    line = data.split(b'\n')[26]  # line 27: '\traise ValueError("raised on line 27")'
    assert line.startswith(b'\traise')
    pieces = {line[start:end] for start, end in positions_of(code, 27)}
    assert b'ValueError("raised on line 27")' in pieces
    assert b'raise ValueError("raised on line 27")' in pieces
    # lines whose indentation did not change keep their columns
    plain_line = data.split(b'\n')[12]  # '        seen += 1'
    assert {plain_line[s:e] for s, e in positions_of(code, 13)} >= {b'seen += 1'}


@needs_columns
def test_location_tables_read_and_written_as_cpython_does():
    import json
    import textwrap
    for module in (json, textwrap, ast):
        with open(module.__file__, 'rb') as f:
            top = compile(f.read(), module.__file__, 'exec')
        stack = [top]
        while stack:
            code = stack.pop()
            stack.extend(c for c in code.co_consts if hasattr(c, 'co_code'))
            entries = exp2_code_columns.decode(code.co_linetable, code.co_firstlineno)
            assert [e[1:] for e in entries for _ in range(e[0])] == list(code.co_positions())
            table = exp2_code_columns.encode(entries, code.co_firstlineno)
            again = code.replace(co_linetable=table)
            assert list(again.co_positions()) == list(code.co_positions())
            assert list(again.co_lines()) == list(code.co_lines())


def first_statement(source):
    return ast.parse(source).body[0]


@pytest.mark.parametrize('source,is_import', [
    ('import os', True),
    ('from os import path', True),
    ('"""docstring"""', True),
    ('sys.path.append("/x")', True),
    ('try:\n    import smach\nexcept ImportError:\n    pass', True),
    ('if True:\n    import a\nelse:\n    import b', True),
    ('rospy.init_node("x")', False),
    ('x = 1', False),
    ('def f():\n    import os', False),
    ('try:\n    import a\nexcept ImportError:\n    a = None', False),
    ('if __name__ == "__main__":\n    main()', False),
])
def test_the_line_waits_for_the_end_of_the_imports(source, is_import):
    assert exp2_tab_report._is_import_statement(first_statement(source)) is is_import

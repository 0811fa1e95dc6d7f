"""How the original-code shell starts a node's file (src/exp_assignment2/original_env/startup/
exp2_node_start.py), as plain functions: which first lines name Python 2, and
the command for a file without its execute bit. No ROS master."""
import os
import sys

import pytest

STARTUP = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(
    __file__)))), 'src', 'exp_assignment2', 'original_env', 'startup')
sys.path.insert(0, STARTUP)
import exp2_node_start  # noqa: E402


@pytest.fixture(autouse=True)
def no_shell(monkeypatch):
    monkeypatch.delenv('EXP2_ORIGINAL_BIN', raising=False)


@pytest.mark.parametrize('line,python2', [
    ('#!/usr/bin/python', True), ('#! /usr/bin/python', True), ('#!/usr/bin/python2', True),
    ('#!/usr/bin/python2.7', True), ('#!/usr/bin/env python', True),
    ('#!/usr/bin/env python2', True), ('#!/usr/bin/env -S python -u', True),
    ('#!/usr/bin/python3', False), ('#!/usr/bin/env python3', False), ('#!/bin/bash', False),
    ('import os', False),
])
def test_first_lines_that_name_python_2(tmp_path, line, python2):
    path = tmp_path / 'node.py'
    path.write_text(line + '\nprint(1)\n')
    assert exp2_node_start.names_python_not_3(exp2_node_start.shebang(str(path))) is python2


@pytest.mark.parametrize('line,mode,expected', [
    ('#!/usr/bin/python', 0o755, ['/usr/bin/python3', 'F']),
    ('#!/usr/bin/python3', 0o755, None),
    ('#!/usr/bin/python3', 0o644, ['/usr/bin/python3', 'F']),
    ('#!/usr/bin/env python3', 0o644, ['/usr/bin/python3', 'F']),
    ('#!/bin/bash', 0o644, ['/bin/bash', 'F']),
    ('print(1)', 0o644, ['/usr/bin/python3', 'F']),
])
def test_the_command_that_starts_a_file(tmp_path, line, mode, expected):
    path = tmp_path / 'node.py'
    path.write_text(line + '\n')
    path.chmod(mode)
    command = exp2_node_start.command(str(path))
    assert command == (None if expected is None else [str(path) if w == 'F' else w
                                                      for w in expected])
    assert path.stat().st_mode & 0o777 == mode


def test_a_file_without_a_first_line_or_py_suffix_is_left_to_ros(tmp_path):
    path = tmp_path / 'tool'
    path.write_text('echo hi\n')
    path.chmod(0o644)
    assert exp2_node_start.command(str(path)) is None

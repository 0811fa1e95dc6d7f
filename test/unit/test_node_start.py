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


class _FakeNodeArgs(object):
    """roslaunch.node_args as far as the patch uses it: a node found only under
    the names in ``files``."""

    class NodeParamsException(Exception):
        pass

    def __init__(self, files):
        import types
        self.files = files
        self.roslib = types.SimpleNamespace(packages=types.SimpleNamespace(
            find_node=lambda package, name: list(files.get((package, name), []))))

        def create_local_process_args(node, machine, env=None):
            found = self.roslib.packages.find_node(node.package, node.type)
            if not found:
                raise self.NodeParamsException('Cannot locate node of type [%s]' % node.type)
            return [found[0], '__name:=' + node.name]
        self.create_local_process_args = create_local_process_args


def test_a_node_type_noetic_renamed_starts_under_its_new_name(tmp_path, monkeypatch, capsys):
    """Kinetic's launch files say robot_state_publisher/state_publisher; Noetic
    has only robot_state_publisher/robot_state_publisher: that is started, and
    one line says so; a type that exists under neither name still fails."""
    import types
    program = tmp_path / 'robot_state_publisher'
    program.write_text('#!/bin/sh\n')
    program.chmod(0o755)
    fake = _FakeNodeArgs({('robot_state_publisher', 'robot_state_publisher'): [str(program)]})
    monkeypatch.setattr(exp2_node_start, 'find_file', lambda package, name: (None, False))
    exp2_node_start._patch_node_args(fake)
    node = types.SimpleNamespace(package='robot_state_publisher', type='state_publisher',
                                 name='rsp')
    assert fake.create_local_process_args(node, None) == [str(program), '__name:=rsp']
    fake.create_local_process_args(node, None)
    said = capsys.readouterr().err
    assert said.count('robot_state_publisher/state_publisher: started as '
                      'robot_state_publisher/robot_state_publisher') == 1, said
    missing = types.SimpleNamespace(package='robot_state_publisher', type='no_such', name='x')
    with pytest.raises(fake.NodeParamsException):
        fake.create_local_process_args(missing, None)

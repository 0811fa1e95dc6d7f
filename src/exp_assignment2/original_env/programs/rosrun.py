#!/usr/bin/python3
"""``rosrun`` of the original-code shell (environment.py copies it, executable, to
$EXP2_ORIGINAL_BIN/rosrun, first on PATH).

It is ROS's rosrun, except where the students' machines started a file that
ROS's rosrun here would not: a script whose first line names Python 2
(``#!/usr/bin/python``) runs on this shell's ``python``, and a file that lost
its execute bit runs as if it had it, with one stderr line naming it
(startup/exp2_node_start.py decides both), and a node type Noetic renamed
(``robot_state_publisher state_publisher``) runs under its Noetic name, with
one line. Everything else, and every case it
does not recognise, goes to ROS's rosrun unchanged.
"""
import os
import shutil
import sys


def real_rosrun():
    own = os.path.dirname(os.path.abspath(__file__))
    path = os.pathsep.join(d for d in os.environ.get('PATH', '').split(os.pathsep)
                           if d and os.path.abspath(d) != own)
    return shutil.which('rosrun', path=path) or '/usr/bin/rosrun'


def main(argv):
    real = [real_rosrun()] + argv
    prefix, rest = [], list(argv)
    while rest and rest[0] in ('--prefix', '-p', '--debug', '-d'):
        if rest[0] in ('--prefix', '-p'):
            if len(rest) < 2:
                return real
            prefix += rest[1].split()
            rest = rest[2:]
        else:
            rest = rest[1:]
    if len(rest) < 2 or '/' in rest[1] or os.environ.get('EXP2_NODE_START', '1') == '0':
        return real
    try:
        import exp2_node_start      # startup/, first on this shell's PYTHONPATH
    except ImportError:
        return real
    try:
        path, executable = exp2_node_start.find_file(rest[0], rest[1])
        new = exp2_node_start.renamed(rest[0], rest[1]) if path is None else None
        if new is not None and exp2_node_start.find_file(rest[0], new)[0]:
            exp2_node_start.tell_renamed(rest[0], rest[1])
            return [real_rosrun()] + argv[:len(argv) - len(rest)] + [rest[0], new] + rest[2:]
    except Exception:       # no such package: ROS's rosrun says so
        return real
    start = exp2_node_start.command(path) if path else None
    if start is None:
        return real
    if not executable:
        exp2_node_start.tell_not_executable([path])
    return prefix + start + rest[2:]


if __name__ == '__main__':
    command = main(sys.argv[1:])
    os.execvp(command[0], command)

"""A teacher's ``SUBMISSIONS/grading.yaml``, read and checked (no ROS): each
mistake is one line naming it (:class:`TeacherFileError`); a mistake in one
submission's settings costs that submission only. Its keys are in
docs/grading.md; a command is a line or ``{run: LINE, after: S | at: S,
cwd: FOLDER}`` (when it starts, from which folder of the submission:
:mod:`~exp_assignment2.grading.plan.starts`).
"""
import datetime
import difflib
import os

import yaml

from exp_assignment2.grading.entry import deadlines
from exp_assignment2.grading.teacher_error import TeacherFileError
from exp_assignment2.sim.releases import RELEASES

TOP_KEYS = {'profile': str, 'duration': (int, float), 'commands': list, 'delay': (int, float),
            'real_time_factor': (int, float), 'submissions': dict, 'with': list,
            'template': (list, str),     # the similarity report's (similarity_run.py)
            'release': str,              # the course's first ROS release (ros_release.py)
            # a term's dates and marks (deadlines.py, git_entries.py, report/gradebook.py)
            'deadline': (str, datetime.date), 'extensions': dict, 'late': dict,
            'students': dict, 'gradebook': dict}
ONE_KEYS = {'commands': list, 'skip': bool, 'roles': dict, 'release': str,
            # a git repository graded at a commit chosen on purpose (deadlines.py)
            'commit': (str, int, float), 'at': (str, datetime.date)}
# the gradebooks' grade column, and Canvas's column of the identifier (report/gradebook.py)
GRADEBOOK_KEYS = {'assignment': str, 'canvas_column': str}
ROLE_KEYS = ('robot', 'head', 'ball')     # a submission's roles named by the teacher (roles.py)
RELEASE_NAMES = tuple(RELEASES)      # the releases the simulator can play
# a command of grading.yaml written as a mapping: its line, when, from where
START_KEYS = {'run': str, 'after': (int, float), 'at': (int, float), 'cwd': str,
              'input': (list, dict)}     # lines to type: the original-code environment's keyboard


def _check_keys(data, allowed, where):
    for key, value in data.items():
        if key not in allowed:
            close = difflib.get_close_matches(str(key), list(allowed), n=1)
            raise TeacherFileError('%s: unknown key %r%s (known: %s)' % (
                where, key, ' (did you mean %r?)' % close[0] if close else '',
                ', '.join(sorted(allowed))))
        if not isinstance(value, allowed[key]) or isinstance(value, bool) and \
                allowed[key] is not bool:
            raise TeacherFileError('%s: %s: %r is not a %s' % (
                where, key, value, getattr(allowed[key], '__name__', 'number')))
    for command in data.get('commands') or []:
        _check_command(command, where)
    for key in ('duration', 'delay', 'real_time_factor'):
        if key in data and not (0 <= data[key] <= 100000):
            raise TeacherFileError('%s: %s: %r is out of range' % (where, key, data[key]))
    if 'release' in data and data['release'] not in RELEASE_NAMES:
        raise TeacherFileError('%s: release: %r is not one of %s' % (
            where, data['release'], ', '.join(RELEASE_NAMES)))
    for key, name in (data.get('roles') or {}).items():
        if key not in ROLE_KEYS or not isinstance(name, str) or not name.strip():
            raise TeacherFileError('%s: roles: %r: %r is not one of %s naming a model or joint'
                                   % (where, key, name, ', '.join(ROLE_KEYS)))


def _check_command(command, where):
    """A command of grading.yaml: a line, or {run: LINE, after: S or at: S, cwd: FOLDER}."""
    if isinstance(command, str) and command.strip():
        return
    if not isinstance(command, dict):
        raise TeacherFileError('%s: commands: each must be a command line (a string) or '
                               '{run: LINE, after: S, cwd: FOLDER}: %r' % (where, command))
    _check_keys(command, START_KEYS, '%s: commands: %s' % (where, command.get('run', command)))
    if not (command.get('run') or '').strip():
        raise TeacherFileError('%s: commands: %r has no run: (the command line)'
                               % (where, command))
    if 'after' in command and 'at' in command:
        raise TeacherFileError('%s: commands: %s: after: or at:, not both'
                               % (where, command['run']))
    for key in ('after', 'at'):
        if key in command and not (0 <= command[key] <= 100000):
            raise TeacherFileError('%s: commands: %s: %s: %r is out of range'
                                   % (where, command['run'], key, command[key]))
    cwd = command.get('cwd', '')
    if os.path.isabs(cwd) or cwd.startswith('~') or '..' in cwd.split('/'):
        raise TeacherFileError('%s: commands: %s: cwd: %r must be a folder of the submission '
                               '(relative to its root)' % (where, command['run'], cwd))
    if 'input' in command:
        _check_input(command['input'], '%s: commands: %s: input' % (where, command['run']))


def _check_input(given, where):
    """``input:``, the lines a person types into the command's keyboard: a list of
    {at: SIMULATED_S, text: LINE}, or such lists by node name, script name or '*'."""
    lists = list(given.values()) if isinstance(given, dict) else [given]
    for lines in lists:
        if not isinstance(lines, list):
            raise TeacherFileError('%s: a list of {at: S, text: LINE}, or such lists by node '
                                   'or script name' % where)
        for line in lines:
            at = line.get('at') if isinstance(line, dict) else None
            text = line.get('text') if isinstance(line, dict) else None
            if not isinstance(line, dict) or set(line) - {'at', 'text'} or \
                    isinstance(at, bool) or not isinstance(at, (int, float)) or \
                    not 0 <= at <= 100000 or not isinstance(text, str) or '\n' in text:
                raise TeacherFileError('%s: %r is not {at: SIMULATED_S, text: ONE_LINE}'
                                       % (where, line))


def read_teacher_file(path):
    """The teacher's settings (a dict, checked); {} when there is no file."""
    if not path or not os.path.isfile(path):
        return {}
    name = os.path.basename(path)
    try:
        with open(path) as f:
            data = yaml.safe_load(f)
    except (yaml.YAMLError, UnicodeDecodeError) as exc:
        raise TeacherFileError('%s: not YAML: %s' % (name, str(exc).splitlines()[0]))
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise TeacherFileError('%s: must be a mapping of settings' % name)
    _check_keys(data, TOP_KEYS, name)
    _check_term(data, name)
    # a mistake in one submission's settings costs that submission only: it is
    # kept in 'errors' (the grader reports it for that one) and its settings dropped
    data['errors'] = {}
    for who, settings in list((data.get('submissions') or {}).items()):
        try:
            if not isinstance(settings, dict):
                raise TeacherFileError('%s: submissions: %s: must be a mapping' % (name, who))
            _check_keys(settings, ONE_KEYS, '%s: submissions: %s' % (name, who))
            deadlines.check_own(settings, '%s: submissions: %s' % (name, who))
        except TeacherFileError as exc:
            data['errors'][str(who)] = str(exc)
            del data['submissions'][who]
    return data


def _check_term(data, name):
    """The term's keys: dates and the late policy (deadlines.py), ``students:``
    (each submission's identifier in the gradebooks: a string, or a number) and
    ``gradebook:``."""
    deadlines.check(data, name)
    for who, ident in (data.get('students') or {}).items():
        if isinstance(ident, bool) or not isinstance(ident, (str, int)) or not str(ident).strip():
            raise TeacherFileError('%s: students: %s: %r is not an identifier (a string or '
                                   'a number)' % (name, who, ident))
    _check_keys(data.get('gradebook') or {}, GRADEBOOK_KEYS, '%s: gradebook' % name)
    column = (data.get('gradebook') or {}).get('canvas_column')
    if column is not None and column not in ('ID', 'SIS User ID', 'SIS Login ID'):
        raise TeacherFileError("%s: gradebook: canvas_column: %r is not one of 'ID', "
                               "'SIS User ID', 'SIS Login ID'" % (name, column))

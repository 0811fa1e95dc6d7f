"""How a submission is started (no ROS): its README's ``roslaunch`` and
``rosrun`` lines, a teacher's ``grading.yaml``, or the profile's default.

The README is read as a student writes one: commands in fenced blocks and in
inline code, after a shell prompt or ``&&``, in their order, each once.
Viewers a headless run has no use for (rqt, rviz, smach_viewer) are left out
with a note.
"""
import difflib
import os
import re
import shlex

import yaml

README_NAMES = ('README.md', 'README.MD', 'Readme.md', 'readme.md', 'README', 'README.txt',
                'README.rst')
VIEWERS = re.compile(r'^(rqt\w*|rviz|smach_viewer|image_view|rqt_image_view|rqt_graph)$')
COMMAND = re.compile(r'\b(roslaunch|rosrun)\s+[^`\n;|&]+')
PLACEHOLDER = re.compile(r'[<>{}\[\]]|\.\.\.|\bYOUR_|\bpackage_name\b', re.IGNORECASE)

TOP_KEYS = {'profile': str, 'duration': (int, float), 'commands': list, 'delay': (int, float),
            'real_time_factor': (int, float), 'submissions': dict, 'with': list}
ONE_KEYS = {'commands': list, 'skip': bool}


class TeacherFileError(Exception):
    """One line naming the mistake in grading.yaml."""


class Start(object):
    """The commands to run for one submission and where they came from."""

    def __init__(self, commands, source, notes=()):
        self.commands, self.source, self.notes = list(commands), source, list(notes)

    def as_dict(self):
        return {'commands': self.commands, 'source': self.source, 'notes': self.notes}


def _code_texts(text):
    """The README's code: fenced blocks' lines and inline code spans."""
    texts, fenced = [], False
    for line in text.splitlines():
        if re.match(r'^\s*(```|~~~)', line):
            fenced = not fenced
            continue
        if fenced or line.startswith('    ') or line.startswith('\t'):
            texts.append(line)
        else:
            texts.extend(re.findall(r'`([^`\n]+)`', line))
    return texts


def _clean(command):
    command = command.strip().rstrip('\\').strip()
    command = re.split(r'\s#', command)[0].strip()   # a shell comment after it
    return command


def readme_commands(package_dir):
    """(commands, notes, readme name or None) from the package's README."""
    for name in README_NAMES:
        path = os.path.join(package_dir, name)
        if os.path.isfile(path):
            break
    else:
        return [], [], None
    with open(path, errors='replace') as f:
        text = f.read(1 << 20)
    commands, notes = [], []
    for code in _code_texts(text):
        for match in COMMAND.finditer(code):
            command = _clean(match.group(0))
            try:
                words = shlex.split(command)
            except ValueError:
                continue
            if len(words) < 3 and not (words[0] == 'roslaunch' and len(words) == 2
                                       and words[1].endswith('.launch')):
                continue
            if PLACEHOLDER.search(command):
                continue
            if words[0] == 'rosrun' and VIEWERS.match(words[1]):
                notes.append('%s: a viewer, left out of a headless run' % command)
                continue
            if command not in commands:
                commands.append(command)
    return commands, notes, name


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
    for key in ('commands',):
        if key in data and not all(isinstance(c, str) and c.strip() for c in data[key]):
            raise TeacherFileError('%s: commands: each must be a command line (a string)'
                                   % where)
    for key in ('duration', 'delay', 'real_time_factor'):
        if key in data and not (0 <= data[key] <= 100000):
            raise TeacherFileError('%s: %s: %r is out of range' % (where, key, data[key]))


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
    # a mistake in one submission's settings costs that submission only: it is
    # kept in 'errors' (the grader reports it for that one) and its settings dropped
    data['errors'] = {}
    for who, settings in list((data.get('submissions') or {}).items()):
        try:
            if not isinstance(settings, dict):
                raise TeacherFileError('%s: submissions: %s: must be a mapping' % (name, who))
            _check_keys(settings, ONE_KEYS, '%s: submissions: %s' % (name, who))
        except TeacherFileError as exc:
            data['errors'][str(who)] = str(exc)
            del data['submissions'][who]
    return data


def start_for(package_dir, package, submission_name, teacher, profile_commands,
              teacher_file='grading.yaml'):
    """The :class:`Start` of one submission: the teacher's commands for it,
    the teacher's for all, its README's, or the profile's default (with the
    package's name put in for ``{package}``)."""
    own = (teacher.get('submissions') or {}).get(submission_name) or {}
    if own.get('commands'):
        return Start(own['commands'], '%s (submissions: %s)' % (teacher_file, submission_name))
    if teacher.get('commands'):
        return Start(teacher['commands'], '%s (commands)' % teacher_file)
    commands, notes, readme = readme_commands(package_dir)
    if commands:
        return Start(commands, 'the submission\'s %s' % readme, notes)
    notes.append('no roslaunch or rosrun line in %s: the profile\'s default'
                 % (readme or 'a README (there is none)'))
    return Start([c.format(package=package) for c in profile_commands],
                 'the profile\'s default', notes)

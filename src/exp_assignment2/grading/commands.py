"""What a submission's README and a teacher's ``grading.yaml`` say (no ROS).

The README is read as a student writes one: commands in fenced blocks,
indented blocks and inline code, after a shell prompt or ``&&``, in their
order, each once. Each command found is one of: a ``roslaunch``/``rosrun``
line (``ros``), a command for another shell that only watches (``watch``:
``rostopic echo``, ``rqt_graph``, ``rviz``, ...), or a start script the README
runs (``script``: ``./run.sh``, ``bash start.sh``), whose own ``roslaunch``/
``rosrun`` lines (also inside ``gnome-terminal -x sh -c "..."`` or ``xterm -e``)
follow it. What runs of them is decided in :mod:`.choose`.
"""
import difflib
import os
import re
import shlex

import yaml

from exp_assignment2.sim.releases import RELEASES

README_NAMES = ('README.md', 'README.MD', 'Readme.md', 'readme.md', 'README', 'README.txt',
                'README.rst')
# packages of programs that only watch (rosrun rqt_graph rqt_graph, ...)
VIEWERS = re.compile(r'^(rqt\w*|rviz|smach_viewer|image_view|rqt_image_view|rqt_graph)$')
# one shell command: what follows a prompt, ``&&``, ``;`` or ``|``
STARTS = re.compile(
    r'(?:^|\s)((?:roslaunch|rosrun)\s.*'
    r'|(?:rostopic\s+(?:echo|hz|list|info|bw|type|find)|rosnode\s+\w+|rosservice\s+(?:list|info)'
    r'|rosparam\s+(?:get|list)|rqt\w*|rviz|smach_viewer|image_view)(?:\s.*)?'
    r'|(?:\./|(?:bash|sh)\s+)(?![\w./-]*setup\.sh)[\w./-]+\.sh\b.*)$')
IN_SCRIPT = re.compile(r'\b(?:roslaunch|rosrun)\s+[^`\n;|&"\']+')
PLACEHOLDER = re.compile(r'[<>{}\[\]]|\.\.\.|\bYOUR_|\bpackage_name\b', re.IGNORECASE)

TOP_KEYS = {'profile': str, 'duration': (int, float), 'commands': list, 'delay': (int, float),
            'real_time_factor': (int, float), 'submissions': dict, 'with': list,
            'template': (list, str),     # the similarity report's (similarity_run.py)
            'release': str}              # the course's first ROS release (ros_release.py)
ONE_KEYS = {'commands': list, 'skip': bool, 'roles': dict, 'release': str}
ROLE_KEYS = ('robot', 'head', 'ball')     # a submission's roles named by the teacher (roles.py)
RELEASE_NAMES = tuple(RELEASES)      # the releases the simulator can play


class TeacherFileError(Exception):
    """One line naming the mistake in grading.yaml."""


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
    command = command.rstrip('&').strip()
    for quote in '"\'':          # the end of a ``sh -c "..."`` around it
        if command.count(quote) % 2:
            command = command.rstrip(quote).strip()
    return command


def kind_of(command):
    """'ros', 'watch' or 'script' for a command line (None: none of them, or
    a placeholder such as ``roslaunch <your_package> file.launch``)."""
    try:
        words = shlex.split(command)
    except ValueError:
        return None
    if not words or PLACEHOLDER.search(command):
        return None
    if words[0] in ('roslaunch', 'rosrun'):
        if len(words) < 3 and not (words[0] == 'roslaunch' and len(words) == 2
                                   and words[1].endswith('.launch')):
            return None
        if words[0] == 'rosrun' and VIEWERS.match(words[1]):
            return 'watch'
        return 'ros'
    if words[0].endswith('.sh') or len(words) > 1 and words[1].endswith('.sh'):
        return 'script'
    return 'watch'


def _commands_in(code):
    """The commands of one line of code, in their order."""
    found = []
    for segment in re.split(r'&&|;|\|\|?', code):
        match = STARTS.search(segment.strip())
        if match:
            found.append(_clean(match.group(1)))
    return found


def script_commands(package_dir, command):
    """(the script's path relative to the package or None, its ``roslaunch``/
    ``rosrun`` lines) for ``./run.sh`` or ``bash start.sh``: found by its name
    where the README says, else anywhere in the package."""
    words = shlex.split(command)
    rel = words[0] if words[0].endswith('.sh') else words[1]
    path = os.path.normpath(os.path.join(package_dir, rel))
    if not (path.startswith(package_dir + os.sep) and os.path.isfile(path)):
        path = None
        for root, dirs, files in os.walk(package_dir):
            dirs.sort()
            if os.path.basename(rel) in files:
                path = os.path.join(root, os.path.basename(rel))
                break
    if path is None:
        return None, []
    with open(path, errors='replace') as f:
        text = f.read(1 << 20)
    commands = []
    for line in text.splitlines():
        if line.lstrip().startswith('#'):
            continue
        commands.extend(_clean(m.group(0)) for m in IN_SCRIPT.finditer(line))
    return os.path.relpath(path, package_dir), commands


def readme_entries(package_dir):
    """([{'command', 'kind', 'from'}], readme name or None): every command
    the README gives, in order, each once; a start script's lines follow it."""
    for name in README_NAMES:
        path = os.path.join(package_dir, name)
        if os.path.isfile(path):
            break
    else:
        return [], None
    with open(path, errors='replace') as f:
        text = f.read(1 << 20)
    entries, seen = [], set()

    def add(command, where):
        kind = kind_of(command)
        if kind and command not in seen:
            seen.add(command)
            entries.append({'command': command, 'kind': kind, 'from': where})
            return kind
    for code in _code_texts(text):
        for command in _commands_in(code):
            if add(command, name) == 'script':
                script, inside = script_commands(package_dir, command)
                entries[-1]['script'] = script
                for line in inside:
                    add(line, script)
    return entries, name


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
    if 'release' in data and data['release'] not in RELEASE_NAMES:
        raise TeacherFileError('%s: release: %r is not one of %s' % (
            where, data['release'], ', '.join(RELEASE_NAMES)))
    for key, name in (data.get('roles') or {}).items():
        if key not in ROLE_KEYS or not isinstance(name, str) or not name.strip():
            raise TeacherFileError('%s: roles: %r: %r is not one of %s naming a model or joint'
                                   % (where, key, name, ', '.join(ROLE_KEYS)))


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

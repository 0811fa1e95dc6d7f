"""What a submission's README and a teacher's ``grading.yaml`` say (no ROS).

The README is read as a student writes one, and as a person reads it: commands in fenced blocks,
indented blocks and inline code, after a shell prompt or ``&&``, in their order, each once. Each
command found is one of: a ``roslaunch``/``rosrun`` line (``ros``), a command for another shell
that only watches (``watch``: ``rostopic echo``, ``rqt_graph``, ``rviz``, ...), a build step
(``build``: ``catkin_make``, ``catkin build``, ``source devel/setup.bash``, ``rosdep install``,
``chmod +x``), or a start script the README runs (``script``: ``./run.sh``, ``bash start.sh``),
whose own ``roslaunch``/``rosrun`` lines follow it, each with the time its shell starts it
(:mod:`~exp_assignment2.grading.plan.start_script`). A ``cd``/``roscd`` changes the folder of the
commands after it, inside the submission (:func:`~exp_assignment2.grading.plan.own_names.cd`). What
runs of them is decided in :mod:`~exp_assignment2.grading.plan.choose`.
"""
import os
import re

from exp_assignment2.grading.plan import own_names
from exp_assignment2.grading.plan import shell
from exp_assignment2.grading.plan import start_script
from exp_assignment2.grading.plan.typed import code_texts, typed
from exp_assignment2.grading.entry.reading import read_text
# grading.yaml's reader, where the grader has always found it
from exp_assignment2.grading.plan.teacher_file import (  # noqa: F401 (the door to them)
    TeacherFileError, read_teacher_file)

README_NAMES = ('README.md', 'README.MD', 'Readme.md', 'readme.md', 'README', 'README.txt',
                'README.rst')
# packages of programs that only watch (rosrun rqt_graph rqt_graph, ...)
VIEWERS = re.compile(r'^(rqt\w*|rviz|smach_viewer|image_view|rqt_image_view|rqt_graph)$')
# one shell command, after a prompt
STARTS = re.compile(
    r'(?:^|\s)((?:roslaunch|rosrun)\s.*'
    r'|(?:rostopic\s+(?:echo|hz|list|info|bw|type|find)|rosnode\s+\w+|rosservice\s+(?:list|info)'
    r'|rosparam\s+(?:get|list)|rqt\w*|rviz|smach_viewer|image_view)(?:\s.*)?'
    r'|(?:\./|(?:bash|sh)\s+)(?![\w./-]*setup\.sh)[\w./-]+\.sh\b.*)$')
BUILD = re.compile(
    r'(?:^|\s)((?:catkin_make(?:_isolated)?|catkin\s+(?:build|make))(?:\s.*)?'
    r'|(?:source|\.)\s+\S*setup\.(?:bash|sh|zsh)\b.*|rosdep\s+install\b.*|chmod\s+\S*\+x\b.*)$')
CD = re.compile(r'(?:^|[\s$#>])(cd|roscd)(?:\s+(\$\(\s*rospack\s+find\s+[\w-]+\s*\)\S*|\S+))?$')
PLACEHOLDER = re.compile(r'[<>{}\[\]]|\.\.\.|\bYOUR_|\bpackage_name\b', re.IGNORECASE)
# roslaunch's and rosrun's options that take a value
VALUED = {'roslaunch': {'-p', '--port', '-c', '--child', '-u', '--server_uri', '--run_id',
                        '-w', '--numworkers', '-t', '--timeout', '--pid', '--args',
                        '--find-node', '--master-logger-level', '--sigint-timeout',
                        '--sigterm-timeout'},
          'rosrun': {'--prefix'}}
LAUNCH_PATH = ('.launch', '.xml', '.test')


def _clean(command):
    command = command.strip().rstrip('\\').strip()
    command = re.split(r'\s#', command)[0].strip()   # a shell comment after it
    command = command.rstrip('&').strip()
    for quote in '"\'':          # the end of a ``sh -c "..."`` around it
        if command.count(quote) % 2:
            command = command.rstrip(quote).strip()
    return command


def ros_parts(found):
    """{'tool', 'options', 'package', 'name', 'args'} of a ``roslaunch``/
    ``rosrun`` command's words (``package`` None: ``roslaunch PATH``), or None."""
    if not found or found[0] not in VALUED:
        return None
    tool, options, i = found[0], [], 1
    while i < len(found) and found[i].startswith('-'):
        options.append(found[i])
        if found[i] in VALUED[tool] and i + 1 < len(found):
            options.append(found[i + 1])
            i += 1
        i += 1
    rest = found[i:]
    if tool == 'roslaunch' and rest and (rest[0].endswith(LAUNCH_PATH) or '/' in rest[0]):
        return {'tool': tool, 'options': options, 'package': None, 'name': rest[0],
                'args': rest[1:]}
    if len(rest) < 2:
        return None
    return {'tool': tool, 'options': options, 'package': rest[0], 'name': rest[1],
            'args': rest[2:]}


def ros_line(parts):
    """A command line again from :func:`ros_parts`."""
    return shell.joined([parts['tool']] + parts['options'] + (
        [parts['package']] if parts['package'] else []) + [parts['name']] + parts['args'])


def kind_of(command):
    """'ros', 'watch', 'build' or 'script' for a command line (None: none of
    them, or a placeholder such as ``roslaunch <your_package> file.launch``)."""
    words = shell.words(command)
    if not words or PLACEHOLDER.search(command):
        return None
    if words[0] in VALUED:
        parts = ros_parts(words)
        if parts is None:
            return None
        return 'watch' if parts['tool'] == 'rosrun' and VIEWERS.match(parts['package']) \
            else 'ros'
    if BUILD.match(command):
        return 'build'
    if words[0].endswith('.sh') or len(words) > 1 and words[1].endswith('.sh'):
        return 'script'
    return 'watch'


def _pieces(code):
    """[('cd', tool, target) or ('command', text, the mistyped word or None)] of one
    line of code."""
    found = []
    for segment, _ in shell.segments(code):
        match = CD.search(segment)
        if match:
            found.append(('cd', match.group(1), match.group(2) or ''))
            continue
        segment, mistyped = typed(segment)
        match = BUILD.search(segment) or STARTS.search(segment)
        if match:
            found.append(('command', _clean(match.group(1)), mistyped))
    return found


def build_packages(command):
    """The package names a build line names (``--only-pkg-with-deps A``,
    ``-DCATKIN_WHITELIST_PACKAGES="A;B"``, ``catkin build A B``, ``catkin_make
    A``); [] for one that builds everything."""
    words = shell.words(command) or []
    if not words or words[0] not in ('catkin_make', 'catkin_make_isolated', 'catkin'):
        return []
    names, i, listing = [], 2 if words[0] == 'catkin' else 1, False
    while i < len(words):
        word = words[i]
        if word.startswith('-DCATKIN_WHITELIST_PACKAGES=') or \
                word.startswith('-DCATKIN_BUILDLIST_PACKAGES='):
            names += [n for n in re.split(r'[;,\s]+', word.split('=', 1)[1]) if n]
        elif word in ('--only-pkg-with-deps', '--pkg'):
            listing = True
        elif word in ('--cmake-args', '--make-args', '--catkin-make-args'):
            break
        elif word in ('-C', '--directory', '--source', '--build', '-w', '--workspace',
                      '--profile', '-j', '--jobs', '-p', '--parallel-packages'):
            i += 1
        elif not word.startswith('-'):
            names.append(word)
        elif listing:
            listing = False
        i += 1
    return list(dict.fromkeys(names))


def _chain(root, package_dir):
    """The folders from ``root`` down to ``package_dir``, both included."""
    rel = os.path.relpath(package_dir, root)
    if rel == '.' or rel.startswith('..'):
        return [root] if rel == '.' else [root, package_dir]
    parts = rel.split(os.sep)
    return [root] + [os.path.join(root, *parts[:k]) for k in range(1, len(parts) + 1)]


def _readmes(root, package_dir):
    """[(name relative to root, path)]: the root's README, then each README on the
    way down to the main package's folder (a repository of the course: its own
    README, the assignment's folder's, the package's), each when it says something
    else."""
    found = []
    for folder in _chain(root, package_dir):
        for name in README_NAMES:
            path = os.path.join(folder, name)
            if os.path.isfile(path):
                text = read_text(path)
                if all(text != read_text(p) for _, p in found):
                    found.append((os.path.relpath(path, root), path))
                break
    return found


def readme_texts(root, package_dir=None):
    """{name relative to root: text} of the README(s) :func:`readme_entries` reads."""
    return {name: read_text(path) for name, path in _readmes(root, package_dir or root)}


def _script(root, cwd, command):
    """(the script's path relative to root, the folder it runs from) for
    ``./run.sh`` or ``bash start.sh``: where the README is when it says it,
    else found by its name anywhere in the submission (run from its folder);
    (None, cwd) when it is not there."""
    words = shell.words(command)
    rel = words[0] if words[0].endswith('.sh') else words[1]
    for base in (os.path.join(root, cwd), root):
        path = os.path.normpath(os.path.join(base, rel))
        if own_names.inside(root, path) and os.path.isfile(path):
            return os.path.relpath(path, root), cwd
    for path in own_names.files(root).get(os.path.basename(rel), []):
        return os.path.relpath(path, root), _folder(root, os.path.dirname(path))
    return None, cwd


def _folder(root, path):
    """A folder relative to root ('' for the root itself)."""
    rel = os.path.relpath(path, root)
    return '' if rel == '.' else rel


def readme_entries(root, package_dir=None, packages=None):
    """([{'command', 'kind', 'from', 'cwd'}], readme name or None): every
    command the README gives (the root's, then the main package's if it has
    another), in order, each once, with the folder it runs from (relative to ``root``); a start
    script's lines follow it, each with ``of`` (the script's entry) and ``start`` ({'after',
    'since'}: see :mod:`~exp_assignment2.grading.plan.start_script`, ``since`` ('end', k) naming an
    entry); a build
    step has ``packages``. ``packages``: {name: folder} of the submission's."""
    package_dir, packages = package_dir or root, packages or {}
    entries, seen, names = [], {}, []

    def cd(tool, cwd, target):
        return (own_names.roscd if tool == 'roscd' else own_names.cd)(
            root, cwd, target, packages)

    def add(command, where, cwd, **extra):
        kind = kind_of(command)
        # the same command is run once; a path in it means another file from another folder
        key = (command, cwd) if kind == 'script' or kind == 'ros' and ros_parts(
            shell.words(command))['package'] is None else command
        if not kind or key in seen:
            return None
        seen[key] = len(entries)
        entries.append(dict({'command': command, 'kind': kind, 'from': where, 'cwd': cwd},
                            **extra))
        if kind == 'build':
            entries[-1]['packages'] = build_packages(command)
        return len(entries) - 1
    for name, path in _readmes(root, package_dir):
        names.append(name)
        cwd = _folder(root, os.path.dirname(path))
        for code, plain in code_texts(read_text(path)):
            for piece in _pieces(code):
                if piece[0] == 'cd':
                    cwd = cd(piece[1], cwd, piece[2])
                    continue
                extra = dict({'typed': piece[2]} if piece[2] else {}, **(
                    {'plain': True} if plain else {}))
                index = add(piece[1], name, cwd, **extra)
                if index is None or entries[index]['kind'] != 'script':
                    continue
                script, runs_in = _script(root, cwd, piece[1])
                entries[index]['script'] = script
                if script:
                    _add_script(entries, index, add, start_script.read(
                        read_text(os.path.join(root, script)), runs_in, cd))
    if not any(e['kind'] == 'ros' for e in entries):
        _add_found_script(root, package_dir, entries, add, cd)
    return entries, ' and '.join(names) or None


def _add_found_script(root, package_dir, entries, add, cd):
    """A README that starts nothing (no README, or one whose lines only build): a
    person looks in the package for what starts it, and runs its one start script (a
    ``.sh`` whose lines start ROS nodes), from its folder, as the README's own."""
    found = []
    for paths in own_names.files(package_dir).values():
        for path in paths:
            if path.endswith('.sh'):
                folder = _folder(root, os.path.dirname(path))
                starts = start_script.read(read_text(path), folder, cd)
                if any(kind_of(_clean(s['command'])) == 'ros' for s in starts):
                    found.append((path, folder, starts))
    if len(found) != 1:
        return
    path, folder, starts = found[0]
    rel = os.path.relpath(path, root)
    index = add('bash %s' % os.path.basename(path), 'the package', folder, script=rel,
                found='the README starts nothing: the package\'s one start script, %s, '
                      'run as a person looking for how to start it does' % rel)
    if index is not None:
        _add_script(entries, index, add, starts)


def _add_script(entries, index, add, starts):
    """A script's starts as entries after it; a start left out (a duplicate,
    a placeholder) takes no time: what waited for it counts from its own start."""
    script = entries[index]['script']
    placed = []             # per start: its entry index, or its (since, after) if left out
    for start in starts:
        since, after = start['since'], start['after']
        if since is not None:
            waited = placed[since[1]]
            if isinstance(waited, tuple):
                since, after = waited[0], waited[1] + after
            else:
                since = ('end', waited)
        at = add(_clean(start['command']), script, start['cwd'], of=index,
                 start={'after': after, 'since': since})
        placed.append((since, after) if at is None else at)

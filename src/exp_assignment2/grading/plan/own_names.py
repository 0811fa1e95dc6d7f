"""Where things are in a submission, as a person finds them (no ROS, nothing
run): the folder a README's ``cd`` names, each package's launch files and
nodes, and the one name of the submission's own close to a mistyped one.

Every folder found is inside the submission's root: a ``cd`` that leaves it
(``cd ~/catkin_ws``) is its root, where a workspace's ``src`` holds the
submission.
"""
import difflib
import os
import re

from exp_assignment2.grading.entry.reading import read_text

SKIPPED = {'build', 'devel', 'install', 'logs', '__pycache__'}
MAX_FILES = 20000          # a submission's files looked at, at most
LAUNCH_ENDINGS = ('.launch', '.launch.xml', '.test')
# a typo: difflib's ratio of the two names (less their endings, in lower case)
# at least this; 0.8 takes one letter wrong, left out or swapped in a name of
# 5 letters or more (pet_beaviour for pet_behavior: 0.92, world for world1:
# 0.91) and never two names that share only an ending (ball, bell: 0.75)
CLOSE = 0.8
ROSPACK_FIND = re.compile(r'\$\(\s*rospack\s+find\s+([\w-]+)\s*\)')


def inside(root, path):
    path = os.path.normpath(path)
    return path == os.path.normpath(root) or path.startswith(os.path.normpath(root) + os.sep)


def files(folder):
    """{file name: [paths]} under ``folder`` (no hidden folder, no build
    space), at most MAX_FILES."""
    found, count = {}, 0
    for here, dirs, names in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith('.') and d not in SKIPPED)
        for name in sorted(names):
            found.setdefault(name, []).append(os.path.join(here, name))
            count += 1
            if count >= MAX_FILES:
                return found
    return found


def launch_files(package_dir):
    """The names of a package's launch files (roslaunch finds them anywhere in it)."""
    return sorted(n for n in files(package_dir) if n.endswith(LAUNCH_ENDINGS))


def cpp_nodes(package_dir):
    """{executable: [its sources]} from the package's CMakeLists.txt."""
    cmake = read_text(os.path.join(package_dir, 'CMakeLists.txt'))
    return {m.group(1): m.group(2).split() for m in re.finditer(
        r'add_executable\s*\(\s*([\w-]+)\s+([^)]*)\)', cmake)}


def nodes(package_dir):
    """The names ``rosrun`` may run in a package: its Python files, its other
    executable files, its C++ executables."""
    found = set(cpp_nodes(package_dir))
    for name, paths in files(package_dir).items():
        if name.endswith('.py') or any(os.access(p, os.X_OK) for p in paths):
            found.add(name)
    return sorted(found)


def has(package_dir, tool, name):
    """Does the package have this launch file (``roslaunch``) or node (``rosrun``)?"""
    if tool == 'roslaunch':
        return name in files(package_dir)
    return name in files(package_dir) or name in cpp_nodes(package_dir)


def _stem(name):
    name = name.lower()
    for ending in LAUNCH_ENDINGS + ('.py', '.xml'):
        if name.endswith(ending):
            return name[:-len(ending)]
    return name


def closest(name, candidates):
    """The one candidate close to ``name`` (the same less case or ending,
    or within CLOSE), or None when none is, or more than one."""
    stem = _stem(name)
    same = [c for c in candidates if _stem(c) == stem]
    if same:
        return same[0] if len(same) == 1 else None
    near = [c for c in candidates
            if difflib.SequenceMatcher(None, stem, _stem(c)).ratio() >= CLOSE]
    return near[0] if len(near) == 1 else None


def _rel(root, path):
    rel = os.path.relpath(path, root)
    return '' if rel == '.' else rel


def cd(root, cwd, target, packages):
    """The folder (relative to ``root``; '' for the root) a ``cd TARGET``
    run in ``cwd`` goes to: the folder itself when it is one of the
    submission's, else the longest tail of its path that names a folder of
    the submission (a package's name standing for its folder), else the root
    (``~``, ``~/catkin_ws``, a workspace's ``src``)."""
    target = (target or '').strip()
    found = ROSPACK_FIND.match(target)
    if found:
        if found.group(1) not in packages:
            return cwd
        target = os.path.join(packages[found.group(1)], target[found.end():].lstrip('/'))
    if target in ('', '~', '-', '$HOME', '${HOME}', '/'):
        return ''
    here = os.path.normpath(os.path.join(root, cwd, target))
    if not target.startswith(('~', '$')) and inside(root, here) and os.path.isdir(here):
        return _rel(root, here)
    parts = [p for p in target.split('/') if p not in ('', '.') and not p.startswith(('~', '$'))]
    if 'src' in parts[:-1] or parts[-1:] == ['src'] and len(parts) > 1:
        parts = parts[parts.index('src') + 1:]      # a workspace's src holds the submission
    for k in range(len(parts)):                     # the longest tail first
        tail = parts[k:]
        if '..' in tail:
            continue
        if tail[0] in packages:
            here = os.path.join(packages[tail[0]], *tail[1:])
        else:
            here = os.path.join(root, *tail)
        if inside(root, here) and os.path.isdir(here):
            return _rel(root, here)
    return ''


def roscd(root, cwd, target, packages):
    """The folder ``roscd PKG[/SUB]`` goes to; an unknown package leaves ``cwd``."""
    package, _, sub = (target or '').partition('/')
    if package not in packages:
        return cwd
    here = os.path.normpath(os.path.join(packages[package], sub))
    if not (inside(root, here) and os.path.isdir(here)):
        here = packages[package]
    return _rel(root, here)

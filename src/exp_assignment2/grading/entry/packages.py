"""The catkin packages of a submission, and which of them a run builds (no ROS).

A student hands in one package, several (a messages package used by a state
machine's, a robot description), a whole catkin workspace (its ``src/``;
``build/`` and ``devel/`` are never copied: :mod:`~exp_assignment2.grading.entry.unpacking`) or a
repository of the course holding several assignments. :func:`find` finds
every package at any depth, as catkin does (a folder with a
``package.xml`` is a package and is not looked into; ``CATKIN_IGNORE``
hides a folder). :func:`choose` then decides what a run builds, as a person
would with ``catkin build PKG`` or ``catkin_make --only-pkg-with-deps``: the
packages the run's commands start, and everything of the submission they
use (package.xml's dependencies, ``$(find X)`` and ``pkg="X"`` in their
launch files, ``import X``/``#include <X/...>`` in their code), in catkin's
dependency order; the others are listed with why they were not built.
"""
import os
import re
import shlex
import xml.etree.ElementTree as ElementTree

from exp_assignment2.grading.entry.unpacking import SKIPPED
from exp_assignment2.grading.entry.reading import READ_LIMIT, read_text

IGNORE_MARKERS = ('CATKIN_IGNORE', 'COLCON_IGNORE', 'AMENT_IGNORE')
DEPEND_TAGS = ('depend', 'build_depend', 'build_export_depend', 'buildtool_depend',
               'exec_depend', 'run_depend', 'test_depend', 'doc_depend')
CODE_SUFFIXES = ('.py', '.cpp', '.cc', '.h', '.hpp', '.launch', '.xml', '.xacro', '.urdf',
                 '.txt', '.yaml', '.world', '.sdf')
NAME = re.compile(r'^[A-Za-z][A-Za-z0-9_]*$')


class Package(object):
    """One package of a submission: ``name``, ``rel`` (its folder relative to
    the submission's root, ``.`` for the root), ``path``, ``depends``
    (package.xml's dependencies of every kind, by name), ``error`` (why its
    package.xml cannot be read, or None)."""

    def __init__(self, name, rel, path, depends=(), error=None):
        self.name, self.rel, self.path = name, rel, path
        self.depends, self.error = list(depends), error

    def __repr__(self):
        return 'Package(%r, %r)' % (self.name, self.rel)


def read_manifest(path):
    """(name, depends, error) of the package.xml in ``path``."""
    folder = os.path.basename(os.path.normpath(path))
    try:
        with open(os.path.join(path, 'package.xml'), 'rb') as f:
            root = ElementTree.fromstring(f.read(READ_LIMIT))
    except (OSError, ElementTree.ParseError) as exc:
        return folder, [], 'package.xml does not parse: %s' % exc
    name = (root.findtext('name') or '').strip()
    depends = []
    for tag in DEPEND_TAGS:
        for element in root.findall(tag):
            text = (element.text or '').strip()
            if text and text not in depends:
                depends.append(text)
    if not NAME.match(name):
        return folder, depends, 'package.xml has no valid <name> (%r)' % name
    return name, depends, None


def find(root):
    """Every package under ``root`` (a list of :class:`Package`, by path)."""
    found = []
    for dirpath, dirnames, filenames in os.walk(root):
        if any(m in filenames for m in IGNORE_MARKERS):
            dirnames[:] = []
            continue
        if 'package.xml' in filenames:
            name, depends, error = read_manifest(dirpath)
            found.append(Package(name, os.path.relpath(dirpath, root), dirpath, depends, error))
            dirnames[:] = []        # catkin does not look inside a package
            continue
        dirnames[:] = sorted(d for d in dirnames if d not in SKIPPED and not d.startswith('.')
                             and not os.path.islink(os.path.join(dirpath, d)))
    return sorted(found, key=lambda p: (p.rel.count(os.sep), p.rel))


def _uses(names):
    """The pattern of another package's use in a file (its name in group 1)."""
    return re.compile(r'(?:\$\(find\s+|pkg\s*=\s*["\']|\bimport\s+|\bfrom\s+|#include\s*[<"]'
                      r'|\bCOMPONENTS\b[^)]*?\b|\$\(find-pkg-share\s+)(%s)\b'
                      % '|'.join(re.escape(n) for n in sorted(names, key=len, reverse=True)))


def references(package, names):
    """The names of ``names`` (other packages of the submission) that this
    package uses: its package.xml, its launch files' ``$(find X)`` and
    ``pkg="X"``, its code's ``import X`` / ``from X.msg`` / ``#include <X/``,
    its CMakeLists.txt's components."""
    used = {d for d in package.depends if d in names}
    wanted = _uses(names)
    for dirpath, dirnames, filenames in os.walk(package.path):
        dirnames[:] = [d for d in dirnames if d not in SKIPPED and not d.startswith('.')]
        for name in filenames:
            if name.endswith(CODE_SUFFIXES) or name == 'CMakeLists.txt' or '.' not in name:
                used.update(wanted.findall(read_text(os.path.join(dirpath, name))))
    used.discard(package.name)
    return used


def _started(command, packages, root=None, cwd=''):
    """The packages (by name) a ``roslaunch``/``rosrun`` command starts, of the
    submission's; a launch file given by its path: the package that holds it, or,
    for a launch file in no package (``roslaunch all.launch`` at a repository's
    root), the packages it starts and finds (``pkg="X"``, ``$(find X)``)."""
    try:
        words = shlex.split(command)
    except ValueError:
        return []
    if not words or words[0] not in ('roslaunch', 'rosrun'):
        return []
    args = [w for w in words[1:] if not w.startswith('-') and ':=' not in w]
    by_name = {p.name: p for p in packages}
    if len(args) >= 2 and args[0] in by_name:
        return [args[0]]
    if words[0] != 'roslaunch' or not args or not args[0].endswith(('.launch', '.xml')):
        return []
    path = os.path.normpath(os.path.join(root, cwd, args[0])) if root else None
    if path and os.path.isfile(path):
        holder = [p for p in packages if path.startswith(os.path.normpath(p.path) + os.sep)]
        if holder:
            return [holder[0].name]
        return sorted(set(_uses(by_name).findall(read_text(path))))
    for package in sorted(packages, key=lambda p: -len(p.rel)):
        if os.path.basename(args[0]) in _launch_files(package):
            return [package.name]
    return []


def _launch_files(package):
    found = set()
    for dirpath, dirnames, filenames in os.walk(package.path):
        dirnames[:] = [d for d in dirnames if d not in SKIPPED and not d.startswith('.')]
        found.update(f for f in filenames if f.endswith('.launch') or f.endswith('.xml'))
    return found


def main_package(packages, launch_names=(), preferred=()):
    """The package a run is about, before its commands are known: the one
    with a launch file the profile starts (``gazebo_world.launch``), else the
    first one ``preferred`` names (the README's commands, in order), else the
    shallowest."""
    usable = [p for p in packages if not p.error] or list(packages)
    for launch in launch_names:
        having = [p for p in usable if launch in _launch_files(p)]
        if having:
            return having[0]
    for name in preferred:
        for package in usable:
            if package.name == name:
                return package
    return usable[0]


def choose(packages, main, commands, also=(), root=None):
    """([{'name', 'rel', 'built', 'why'}] for every package, in the order
    catkin builds them first; the built ones' Packages, ``main`` first).
    What a run builds: ``main``, the packages its ``commands`` start (each a
    line, or a start's {'command', 'cwd'}: a launch file's path is from its folder
    under ``root``), those named in ``also`` (the README's ``catkin build PKG``),
    and everything of the submission they use, transitively. Of two packages with
    one name, the one used (else the shallowest) is built, as catkin takes one."""
    by_name = {}
    for package in packages:
        if package.name not in by_name or package is main:
            by_name[package.name] = package
    names = set(by_name)
    started = [n for c in commands for n in (
        _started(c, list(by_name.values())) if isinstance(c, str) else
        _started(c['command'], list(by_name.values()), root, c.get('cwd') or ''))]
    wanted = [main.name] + [n for n in also if n in names] + started
    uses = {}
    needed, queue = set(), list(wanted)
    while queue:
        name = queue.pop(0)
        if name in needed:
            continue
        needed.add(name)
        uses[name] = references(by_name[name], names)
        queue.extend(sorted(uses[name] - needed))
    order = _build_order(needed, uses)
    listed = []
    for package in packages:
        chosen = by_name.get(package.name) is package and package.name in needed
        if chosen:
            users = sorted(n for n in needed if package.name in uses.get(n, ()))
            why = 'built: %s' % ('the run is about it' if package is main else
                                 'the run starts it' if package.name in started else
                                 'used by %s' % ', '.join(users) if users else
                                 "the README's build line names it")
        elif by_name.get(package.name) is not package:
            why = 'not built: another package named %s (%s) is, as catkin takes one' % (
                package.name, by_name[package.name].rel)
        else:
            why = 'not built: nothing the run starts uses it'
        listed.append({'name': package.name, 'rel': package.rel, 'built': chosen, 'why': why})
    built = [by_name[n] for n in order]
    built.sort(key=lambda p: p is not main)
    return listed, built


def _build_order(needed, uses):
    """catkin's order: a package after those it uses (a cycle: by name)."""
    order, left = [], set(needed)
    while left:
        ready = sorted(n for n in left if not (uses.get(n, set()) & left)) or sorted(left)[:1]
        order.extend(ready)
        left -= set(ready)
    return order

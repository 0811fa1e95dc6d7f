"""Which of a README's commands a run starts, as a person reading it would
(no ROS: the launch files' nodes come from a function given, in the grader
:func:`exp_assignment2.grading.plan.launch_nodes.read`).

For each command the README gives (:func:`~exp_assignment2.grading.plan.commands.readme_entries`),
in order:

* a command for another shell that only watches (``rostopic echo``,
  ``rqt_graph``, ``rviz``) is left out, with why;
* a build step (``catkin_make``, ``catkin build``, ``source
  devel/setup.bash``, ``rosdep install``, ``chmod +x``) is not run: the
  grader builds the submission itself;
* a start script is not run itself: its ``roslaunch``/``rosrun`` lines are,
  by the same rules (they follow it in the list);
* a simulator the profile's world replaces (``stage_ros``; ``gazebo_ros``'s
  gazebo/gzserver and its world launch files, when the profile has
  world_commands) is left out;
* a command that names what is there runs as written (a launch file found
  from the folder it runs in, a package the run has with that launch file or node); else, where the
  submission has what it means, that runs, with why: the same launch file or node in a package of
  the submission (the README was written before package.xml was renamed, or names another of its
  packages), or the one of the submission's names close to it (a typo, a case difference, a node
  without its ``.py``: :func:`~exp_assignment2.grading.plan.own_names.closest`);
* a command that would start a node name an earlier one already starts is
  an alternative the README offers (ROS would shut the first one down): it is
  left out, naming the node and the earlier command. The nodes of a launch
  file are roslaunch's own reading of it (namespace + name, includes
  followed); a ``rosrun``'s is the literal name its source gives
  ``rospy.init_node``/``ros::init`` (``__name:=`` and ``__ns:=`` honoured). A
  command whose nodes cannot be known is run and never counted as an
  alternative: leaving out a command on a guess costs the student more than
  running it.

The profile's world commands are the teacher's and are not compared.
"""
import os
import re

from exp_assignment2.grading.plan import own_names
from exp_assignment2.grading.plan.commands import ros_line, ros_parts
from exp_assignment2.grading.plan.shell import words as shell_words
from exp_assignment2.grading.entry.reading import read_text

SIMULATOR_TYPES = {'gazebo', 'gzserver', 'gzclient', 'debug', 'stageros'}
INIT_PY = re.compile(r'init_node\(\s*[\'"]([^\'"]+)[\'"]([^)]*)\)')
INIT_CPP = re.compile(r'ros::init\s*\([^,]+,[^,]+,\s*"([^"]+)"')
BUILD_STEP = 'a build step: the grader builds the submission itself'


class Context(object):
    """What the choice needs to know of the submission and the run:
    ``package`` (the main package's package.xml name), ``package_dir``,
    ``provided`` (the package names the run's sandbox has besides the
    submission's), ``world`` (does the profile start the world), ``root``
    (the submission's folder as handed in, where a README and ``cd`` paths
    are read from; default the package's) and ``packages`` ({name: folder}
    of every package in the submission; default the main one)."""

    def __init__(self, package, package_dir, provided, world=False, root=None, packages=None):
        self.package, self.package_dir = package, package_dir
        self.provided, self.world = set(provided), world
        self.root = root or package_dir
        self.packages = dict(packages or {package: package_dir})
        self.packages.setdefault(package, package_dir)


def _names(ctx, tool):
    """{package: its launch files (roslaunch) or nodes (rosrun)} of the submission."""
    listing = own_names.launch_files if tool == 'roslaunch' else own_names.nodes
    return {name: listing(folder) for name, folder in sorted(ctx.packages.items())}


def _pick(ctx, holders, prefer):
    """Of the packages that have a name: the one the README named, the main
    one, or the only one (None: several, none of them those)."""
    for package in (prefer, ctx.package):
        if package in holders:
            return package
    return holders[0] if len(holders) == 1 else None


def find_own(ctx, tool, name, prefer=None):
    """(package, name) of the submission's launch file or node that a
    README's ``name`` means: the same name in one package (``prefer`` first), else the one name
    close to it (:func:`~exp_assignment2.grading.plan.own_names.closest`); None."""
    names = _names(ctx, tool)
    holders = [p for p, found in names.items() if name in found]
    if holders:
        package = _pick(ctx, holders, prefer)
        return (package, name) if package else None
    close = own_names.closest(name, sorted({n for found in names.values() for n in found}))
    if close is None:
        return None
    package = _pick(ctx, [p for p, found in names.items() if close in found], prefer)
    return (package, close) if package else None


def own_has(ctx, words):
    """Does the submission have this command's launch file or node (by its
    exact name, in any of its packages)?"""
    parts = ros_parts(words)
    return bool(parts) and any(own_names.has(folder, parts['tool'], parts['name'])
                               for folder in ctx.packages.values())


def _simulator(parts):
    """Is it a simulator that a profile's world replaces?"""
    if parts['package'] == 'stage_ros':
        return True
    if parts['package'] == 'gazebo_ros':
        return parts['tool'] == 'roslaunch' or parts['name'] in SIMULATOR_TYPES
    return False


def rosrun_node(parts, ctx):
    """The resolved name a ``rosrun PKG TYPE`` node takes, or None when it
    cannot be known (another package's program, an anonymous name)."""
    remaps = dict(w.split(':=', 1) for w in parts['args'] if w.startswith('__') and ':=' in w)
    name = remaps.get('__name')
    folder = ctx.packages.get(parts['package'])
    if name is None and folder:
        for path in own_names.files(folder).get(parts['name'], []):
            match = INIT_PY.search(read_text(path))
            if match and 'anonymous' not in match.group(2):
                name = match.group(1)
                break
        for source in (own_names.cpp_nodes(folder).get(parts['name'], [])
                       if name is None else []):        # a C++ node: its sources
            match = INIT_CPP.search(read_text(os.path.join(folder, source)))
            if match:
                name = match.group(1)
                break
    if name is None:
        return None
    ns = remaps.get('__ns', '/')
    return name if name.startswith('/') else '/' + '/'.join(
        p for p in ns.split('/') + [name] if p)


def names_something(parts, cwd, ctx):
    """Does a ``roslaunch``/``rosrun`` name a launch file or node the run has (the
    submission's, by its name or one close to it, or a package the machine has)?"""
    if parts['package'] is None:
        path = os.path.normpath(os.path.join(ctx.root, cwd, parts['name']))
        return own_names.inside(ctx.root, path) and os.path.isfile(path) or \
            find_own(ctx, parts['tool'], os.path.basename(parts['name'])) is not None
    return parts['package'] in ctx.provided and parts['package'] not in ctx.packages or \
        find_own(ctx, parts['tool'], parts['name'], prefer=parts['package']) is not None


def own_command(parts, cwd, ctx):
    """(the parts run, why they differ from the README's, or '') for a
    ``roslaunch``/``rosrun`` of the README: as written when it names what is
    there (a package the run has, a launch file where it runs from); else the
    submission's own launch file or node it means (a package renamed, a
    typo, another package of the submission, a path from elsewhere)."""
    tool, package, name = parts['tool'], parts['package'], parts['name']
    if package is None:                 # roslaunch PATH: from the folder it runs from
        path = os.path.normpath(os.path.join(ctx.root, cwd, name))
        if own_names.inside(ctx.root, path) and os.path.isfile(path):
            return parts, ''
        found = find_own(ctx, tool, os.path.basename(name))
        if found is None:
            return parts, ''
        why = ('there is no %s in %s: runs package %s\'s' % (
            name, cwd or "the submission's folder", found[0]))
    elif package in ctx.packages and own_names.has(ctx.packages[package], tool, name):
        return parts, ''
    elif package not in ctx.packages and package in ctx.provided:
        return parts, ''
    else:
        found = find_own(ctx, tool, name, prefer=package)
        if found is None:
            return parts, ''
        why = ("there is no package %s: runs the submission's own (package.xml names it %s)"
               % (package, found[0]) if package not in ctx.packages else
               '' if found[0] == package else '%s has no %s: runs package %s\'s' % (
                   package, name, found[0]))
    if found[1] != os.path.basename(name):
        why = '; '.join(w for w in (why, "ran `%s` for the README's `%s`" % (
            found[1], os.path.basename(name))) if w)
    return dict(parts, package=found[0], name=found[1]), why


def aliases(entries, ctx):
    """{a package name the README gives: the submission's folder it means},
    for ``$(find NAME)`` in the launch files read."""
    found = {}
    for entry in entries:
        parts = ros_parts(shell_words(entry['command'])) if entry['kind'] == 'ros' else None
        if parts and parts['package'] and parts['package'] not in ctx.packages and \
                parts['package'] not in ctx.provided:
            own = find_own(ctx, parts['tool'], parts['name'])
            if own:
                found.setdefault(parts['package'], ctx.packages[own[0]])
    return found


def _launch_request(key, parts, cwd, ctx):
    if parts['package'] is None:        # roslaunch path/to/file.launch, from its folder
        return {'key': key, 'path': os.path.normpath(os.path.join(ctx.root, cwd,
                                                                  parts['name']))}
    return {'key': key, 'package': parts['package'], 'file': parts['name'],
            'args': [w for w in parts['args'] if ':=' in w]}


def typo_note(entry):
    """The words for a command word the README mistyped (typed.typed)."""
    return 'the README types `%s`: read as `%s`, as the person typing it does after ' \
        '"command not found"' % (entry['typed'], shell_words(entry['command'])[0])


def _left_out(entry):
    """Why an entry is not run by itself (None: it may run)."""
    if entry.get('left_out'):       # decided before: another assignment's part of the README
        return entry['left_out']
    if entry['kind'] == 'watch':
        return 'only watches (a command for another shell): left out'
    if entry['kind'] == 'build':
        return BUILD_STEP + ('; ' + typo_note(entry) if entry.get('typed') else '')
    if entry['kind'] == 'script':
        return ('a start script: its roslaunch/rosrun lines are read, not the script run'
                if entry.get('script') else 'a start script that is not in the submission: '
                'left out')
    return None


def choose(entries, ctx, read_launches):
    """([{'command', 'entry', 'cwd'}] to run, in order (``entry``: its index in
    ``entries``); [{'command', 'ran', 'why', 'kind'}] for every README
    command, ``corrected`` when what ran is not what it names, ``cwd`` its
    folder when not the root, ``from`` the start script it is in).
    ``read_launches(requests)``: {key: {'nodes': [...]} or {'error': why}}
    for launch files (see launch_nodes)."""
    listed, candidates = [], []
    for index, entry in enumerate(entries):
        item = {'command': entry['command'], 'ran': False, 'why': '', 'kind': entry['kind']}
        if entry['from'].endswith('.sh'):
            item['from'] = entry['from']
        if entry.get('cwd'):
            item['cwd'] = entry['cwd']
        listed.append(item)
        item['why'] = _left_out(entry) or ''
        if entry.get('found'):          # the README started nothing: a script found
            item['why'] = entry['found'] + ': its roslaunch/rosrun lines are read'
        if item['why']:
            continue
        parts = ros_parts(shell_words(entry['command']))
        if _simulator(parts) and ctx.world:
            item['why'] = "a simulator the profile's world replaces: left out"
            continue
        if entry.get('plain') and not names_something(parts, entry.get('cwd', ''), ctx):
            item['why'] = 'plain text that names no launch file or node of the run: a ' \
                'sentence, not a command: left out'
            continue
        parts, item['why'] = own_command(parts, entry.get('cwd', ''), ctx)
        if entry.get('typed'):
            item['why'] = '; '.join(w for w in (typo_note(entry), item['why']) if w)
        if item['why']:
            item['corrected'] = True
        item['run'] = ros_line(parts)
        candidates.append((item, parts, index))
    requests = [_launch_request(str(i), parts, entries[index].get('cwd', ''), ctx)
                for i, (item, parts, index) in enumerate(candidates)
                if parts['tool'] == 'roslaunch']
    launched = read_launches(requests) if requests else {}
    started, runs = {}, []      # node name -> the command that starts it
    for i, (item, parts, index) in enumerate(candidates):
        nodes, unknown = [], None
        if parts['tool'] == 'roslaunch':
            got = launched.get(str(i)) or {'error': 'not read'}
            nodes, unknown = got.get('nodes') or [], got.get('error')
        else:
            node = rosrun_node(parts, ctx)
            nodes = [node] if node else []
        twice = [n for n in nodes if n in started]
        if twice:
            item['why'] = 'left out: also starts %s, an alternative to `%s`' % (
                twice[0], started[twice[0]])
            continue
        for node in nodes:
            started[node] = item['command']
        item['ran'] = True
        runs.append({'command': item['run'], 'entry': index,
                     'cwd': entries[index].get('cwd', '')})
        if unknown:
            item['why'] = ((item['why'] + '; ') if item['why'] else '') + (
                'its launch file was not read (%s): run, not compared with the others'
                % unknown)
    for item in listed:
        item.pop('run', None)
    return runs, listed

"""Which of a README's commands a run starts, as a person reading it would
(no ROS: the launch files' nodes come from a function given, in the grader
:func:`exp_assignment2.grading.launch_nodes.read`).

For each command the README gives (:func:`.commands.readme_entries`), in order:

* a command for another shell that only watches (``rostopic echo``,
  ``rqt_graph``, ``rviz``) is left out, with why;
* a start script is not run itself: its ``roslaunch``/``rosrun`` lines are,
  by the same rules (they follow it in the list);
* a simulator the profile's world replaces (``stage_ros``; ``gazebo_ros``'s
  gazebo/gzserver and its world launch files, when the profile has
  world_commands) is left out;
* ``roslaunch``/``rosrun`` of a package the run does not have, where the
  submission's own package has that launch file or node, runs the
  submission's own (the README was written before the package was renamed);
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
import shlex

SIMULATOR_TYPES = {'gazebo', 'gzserver', 'gzclient', 'debug', 'stageros'}
INIT_PY = re.compile(r'init_node\(\s*[\'"]([^\'"]+)[\'"]([^)]*)\)')
INIT_CPP = re.compile(r'ros::init\s*\([^,]+,[^,]+,\s*"([^"]+)"')


class Context(object):
    """What the choice needs to know of the submission and the run:
    ``package`` (package.xml's name), ``package_dir``, ``provided`` (the
    package names the run's sandbox has besides it), ``world`` (does the
    profile start the world)."""

    def __init__(self, package, package_dir, provided, world=False):
        self.package, self.package_dir = package, package_dir
        self.provided, self.world = set(provided), world


def _files_named(package_dir, name):
    found = []
    for root, dirs, files in os.walk(package_dir):
        dirs[:] = sorted(d for d in dirs if not d.startswith('.') and d not in ('build', 'devel'))
        if name in files:
            found.append(os.path.join(root, name))
    return found


def own_has(ctx, words):
    """Does the submission's package have this command's launch file or node?"""
    if words[0] == 'roslaunch':
        return bool(_files_named(ctx.package_dir, words[2]))
    if _files_named(ctx.package_dir, words[2]):
        return True
    return bool(re.search(r'add_executable\s*\(\s*%s\s' % re.escape(words[2]),
                          _read(os.path.join(ctx.package_dir, 'CMakeLists.txt'))))


def _read(path):
    try:
        with open(path, errors='replace') as f:
            return f.read(1 << 20)
    except OSError:
        return ''


def _simulator(words):
    """Is it a simulator that a profile's world replaces?"""
    if words[1] == 'stage_ros':
        return True
    if words[1] == 'gazebo_ros':
        return words[0] == 'roslaunch' or words[2] in SIMULATOR_TYPES
    return False


def rosrun_node(words, ctx):
    """The resolved name a ``rosrun PKG TYPE`` node takes, or None when it
    cannot be known (another package's program, an anonymous name)."""
    remaps = dict(w.split(':=', 1) for w in words[3:] if w.startswith('__') and ':=' in w)
    name = remaps.get('__name')
    if name is None and words[1] == ctx.package:
        for path in _files_named(ctx.package_dir, words[2]):
            match = INIT_PY.search(_read(path))
            if match and 'anonymous' not in match.group(2):
                name = match.group(1)
                break
        if name is None:        # a C++ node: its sources, from CMakeLists.txt
            cmake = _read(os.path.join(ctx.package_dir, 'CMakeLists.txt'))
            sources = re.search(r'add_executable\s*\(\s*%s\s+([^)]*)\)' % re.escape(words[2]),
                                cmake)
            for source in (sources.group(1).split() if sources else []):
                match = INIT_CPP.search(_read(os.path.join(ctx.package_dir, source)))
                if match:
                    name = match.group(1)
                    break
    if name is None:
        return None
    ns = remaps.get('__ns', '/')
    return name if name.startswith('/') else '/' + '/'.join(
        p for p in ns.split('/') + [name] if p)


def _launch_request(key, words, ctx):
    if len(words) == 2:         # roslaunch path/to/file.launch
        return {'key': key, 'path': os.path.join(ctx.package_dir, words[1])}
    return {'key': key, 'package': words[1], 'file': words[2],
            'args': [w for w in words[3:] if ':=' in w]}


def choose(entries, ctx, read_launches):
    """(the commands to run, in order; [{'command', 'ran', 'why'}] for every
    README command). ``read_launches(requests)``: {key: {'nodes': [...]} or
    {'error': why}} for launch files (see launch_nodes)."""
    listed, candidates = [], []
    for entry in entries:
        item = {'command': entry['command'], 'ran': False, 'why': ''}
        if entry['from'].endswith('.sh'):
            item['from'] = entry['from']
        listed.append(item)
        if entry['kind'] == 'watch':
            item['why'] = 'only watches (a command for another shell): left out'
            continue
        if entry['kind'] == 'script':
            item['why'] = ('a start script: its roslaunch/rosrun lines are read, not the '
                           'script run' if entry.get('script') else
                           'a start script that is not in the package: left out')
            continue
        words = shlex.split(entry['command'])
        if len(words) > 2 and _simulator(words) and ctx.world:
            item['why'] = "a simulator the profile's world replaces: left out"
            continue
        if len(words) > 2 and words[1] != ctx.package and words[1] not in ctx.provided \
                and own_has(ctx, words):
            words[1] = ctx.package
            item['why'] = ('there is no package %s: runs the submission\'s own (package.xml '
                           'names it %s)' % (shlex.split(entry['command'])[1], ctx.package))
        item['run'] = ' '.join(shlex.quote(w) for w in words)
        candidates.append((item, words))
    requests = [_launch_request(str(i), words, ctx) for i, (item, words) in
                enumerate(candidates) if words[0] == 'roslaunch']
    launched = read_launches(requests) if requests else {}
    started, commands = {}, []      # node name -> the command that starts it
    for i, (item, words) in enumerate(candidates):
        nodes, unknown = [], None
        if words[0] == 'roslaunch':
            got = launched.get(str(i)) or {'error': 'not read'}
            nodes, unknown = got.get('nodes') or [], got.get('error')
        else:
            node = rosrun_node(words, ctx)
            nodes = [node] if node else []
        twice = [n for n in nodes if n in started]
        if twice:
            item['why'] = 'left out: also starts %s, an alternative to `%s`' % (
                twice[0], started[twice[0]])
            continue
        for node in nodes:
            started[node] = item['command']
        item['ran'] = True
        commands.append(item['run'])
        if unknown:
            item['why'] = ((item['why'] + '; ') if item['why'] else '') + (
                'its launch file was not read (%s): run, not compared with the others'
                % unknown)
    for item in listed:
        item.pop('run', None)
    return commands, listed

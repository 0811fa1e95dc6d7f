"""The profile's default commands, for a submission whose README gives none to
run (no ROS): what a person with no instructions does.

A default runs only where the package has what it names (``roslaunch
{package} gazebo_world.launch`` where there is a ``gazebo_world.launch``):
a launch file the package does not have is never started, as a person would
not type it. In its place, the package's one launch file that starts the rest
(one no other of its launch files includes; of several, the one that starts
the simulator: a person opens the package's launch folder and runs the launch
file that brings up the world), with a note. When no launch file can be told
so, nothing runs in its place and the note says why.
"""
import re

from exp_assignment2.grading.plan import own_names
from exp_assignment2.grading.entry.reading import read_text
from exp_assignment2.grading.plan.shell import words as shell_words

WORLD = re.compile(r'gazebo_ros|spawn_model|empty_world|gzserver|stage_ros|stageros')


def _launch_paths(package_dir):
    return {name: paths[0] for name, paths in own_names.files(package_dir).items()
            if name.endswith(own_names.LAUNCH_ENDINGS)}


def top_launch(package_dir):
    """The package's launch file that starts the rest (its name), or None."""
    paths = _launch_paths(package_dir)
    texts = {name: read_text(path) for name, path in paths.items()}
    includes = {name: {other for other in paths if other != name and re.search(
        r'<include\b[^>]*\bfile\s*=\s*["\'][^"\']*\b' + re.escape(other) + r'["\']', text)}
        for name, text in texts.items()}

    def starts_world(name, seen=()):
        return bool(WORLD.search(texts[name])) or any(
            starts_world(other, seen + (name,)) for other in includes[name] if other not in seen)
    included = set().union(*includes.values()) if includes else set()
    top = sorted(n for n in paths if n not in included and not n.endswith('.test'))
    world = [n for n in top if starts_world(n)]
    for found in (world, top):
        if len(found) == 1:
            return found[0]
    return None


def commands(defaults, package, package_dir):
    """([commands to run], [notes]) of the profile's ``defaults`` (``{package}`` put in)."""
    run, notes = [], []
    for command in defaults:
        words = shell_words(command) or []
        if len(words) < 3 or words[0] != 'roslaunch' or words[1] != package or \
                own_names.has(package_dir, 'roslaunch', words[2]):
            run.append(command)
            continue
        top = top_launch(package_dir)
        if top is None:
            notes.append('the profile\'s default `%s`: %s has no %s, and no one launch file of '
                         'its own starts the rest (%s): not run' % (
                             command, package, words[2], ', '.join(sorted(
                                 _launch_paths(package_dir))) or 'it has none'))
            continue
        line = ' '.join(['roslaunch', package, top] + words[3:])
        notes.append('the profile\'s default `%s`: %s has no %s; ran its launch file that '
                     'starts the rest, `%s`' % (command, package, words[2], line))
        run.append(line)
    return run, notes


"""A README as a person types it (grading.plan.commands, .choose, .packages): a
mistyped command word read as the word meant, commands written as plain text, a
``$(...)`` kept as the shell keeps it, and a launch file outside every package
with the packages it starts built. Each fixture has the shape of a real
submission's case, none of its code."""
import os

import pytest

from exp_assignment2.grading.entry import packages as packages_
from exp_assignment2.grading.plan import assignment
from exp_assignment2.grading.plan.commands import readme_entries
from exp_assignment2.grading.plan.typed import command_word
from exp_assignment2.grading.plan.planning import resolve
from exp_assignment2.grading.plan.shell import words
from readme_packages import DOG, commands_ran, package, reader

FILES = {'launch/gazebo_world.launch': '<launch/>', 'launch/everything.launch': '<launch/>',
         'scripts/state_machine.py': ''}


@pytest.mark.parametrize('typed, meant', [
    ('roslauch', 'roslaunch'), ('roslanch', 'roslaunch'), ('rolaunch', 'roslaunch'),
    ('rosrn', 'rosrun'), ('rosrum', 'rosrun'), ('catkin_mkae', 'catkin_make'),
    ('soruce', 'source'), ('rostopc', 'rostopic'), ('rosservce', 'rosservice'),
    # commands of their own, and words too short or too far to tell
    ('roscd', None), ('rosbag', None), ('rosnode', None), ('rosed', None), ('roscore', None),
    ('rospy', None), ('ros', None), ('rostest', None), ('echo', None), ('roslaunch', 'roslaunch'),
])
def test_a_command_word_within_two_letters_is_the_word_meant(typed, meant):
    assert command_word(typed) == meant


def test_a_mistyped_roslaunch_runs_as_roslaunch_with_a_note(tmp_path):
    """The README writes `roslauch PKG FILE` twice; the person who types it sees
    "command not found" and types roslaunch."""
    root = package(tmp_path, '```\n$ catkin_mkae\n$ roslauch my_pkg gazebo_world.launch\n'
                             '$ rosrn my_pkg state_machine.py\n```\n', FILES)
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader({'gazebo_world.launch': ['/g']}))
    assert got['commands'] == ['roslaunch my_pkg gazebo_world.launch',
                               'rosrun my_pkg state_machine.py']
    ran = commands_ran(got)
    assert ran['roslaunch my_pkg gazebo_world.launch'] == (
        True, 'the README types `roslauch`: read as `roslaunch`, as the person typing it does '
              'after "command not found"')
    assert ran['catkin_make'][0] is False and 'types `catkin_mkae`' in ran['catkin_make'][1]
    assert got['commands_from'] == "the submission's README.md"


def test_commands_written_as_plain_text_are_typed_when_they_name_what_the_run_has(tmp_path):
    """A README with no code marks: `roslaunch my_pkg everything.launch` as a line of
    text runs, before the profile's default; a sentence that begins with roslaunch
    names nothing and is left out."""
    root = package(tmp_path, 'To start it:\n\n1. roslaunch my_pkg everything.launch.\n\n'
                             'roslaunch is the tool that starts it all\n', FILES)
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader({'everything.launch': ['/g']}))
    assert got['commands'] == ['roslaunch my_pkg everything.launch']
    assert commands_ran(got)['roslaunch is the tool that starts it all'] == (
        False, 'plain text that names no launch file or node of the run: a sentence, not a '
               'command: left out')


def test_a_command_substitution_is_one_word_quoted_or_not():
    for line in ('rosrun stage_ros stageros "$(rospack find my pkg)/world/a.world"',
                 'rosrun stage_ros stageros $(rospack find my pkg)/world/a.world'):
        assert words(line) == ['rosrun', 'stage_ros', 'stageros',
                               '$(rospack find my pkg)/world/a.world']
    assert words("echo '$(not a substitution)' x") == ['echo', '$(not a substitution)', 'x']


def test_a_launch_file_outside_every_package_builds_the_packages_it_starts(tmp_path):
    """`roslaunch launch_file.launch` from the repository's folder starts nodes of
    four packages at its root: each is built (roslaunch could not launch a node of a
    package that was not)."""
    root = tmp_path / 'repo'
    root.mkdir()
    names = ('robot_control', 'robot_vision', 'ball_person', 'robot_world', 'unused_pkg')
    for name in names:
        (root / name / 'scripts').mkdir(parents=True)
        (root / name / 'package.xml').write_text('<package><name>%s</name></package>' % name)
    (root / 'launch_file.launch').write_text(
        '<launch><include file="$(find robot_world)/launch/world.launch"/>'
        '<node pkg="robot_control" type="robot_controller.py" name="control"/>'
        '<node pkg="robot_vision" type="vision.py" name="vision"/>'
        '<node pkg="ball_person" type="person.py" name="person"/></launch>')
    (root / 'README.md').write_text('```\ncd repo\nroslaunch launch_file.launch\n```\n')
    found = packages_.find(str(root))
    main = next(p for p in found if p.name == 'robot_control')
    own = {p.name: p.path for p in found}
    got = resolve(main.path, main.name, 'a', {}, DOG, set(own), reader({}), root=str(root),
                  packages=own)
    assert got['commands'] == ['roslaunch launch_file.launch']
    listed, built = packages_.choose(found, main, got['starts'], root=str(root))
    assert sorted(p.name for p in built) == sorted(names[:4])
    assert {p['name']: p['built'] for p in listed}['unused_pkg'] is False


def test_readme_entries_keep_what_was_typed(tmp_path):
    root = package(tmp_path, '    roslauch my_pkg gazebo_world.launch\n', FILES)
    entries, _ = readme_entries(root)
    assert [(e['command'], e.get('typed')) for e in entries] == [
        ('roslaunch my_pkg gazebo_world.launch', 'roslauch')]
    assert os.path.basename(root) == 'my_pkg'


def test_a_course_repository_s_top_readme_runs_no_other_exercise(tmp_path):
    """A repository of the course's exercises: its top README starts exercise 1 (a
    Stage world, quoted ``$(rospack find ...)``, and exercise 1's node); the
    assignment's folder has its own README with its roslaunch. Only that runs."""
    root = tmp_path / 'course'
    (root / 'exercise1' / 'world').mkdir(parents=True)
    (root / 'exercise1' / 'package.xml').write_text('<package><name>exercise1</name></package>')
    (root / 'assignment2' / 'launch').mkdir(parents=True)
    (root / 'assignment2' / 'package.xml').write_text(
        '<package><name>exp_assignment2</name></package>')
    (root / 'assignment2' / 'launch' / 'gazebo_world.launch').write_text('<launch/>')
    (root / 'README.md').write_text(
        '# Exercise 1\n```\nrosrun stage_ros stageros "$(rospack find exercise1)/world/'
        'exercise.world"\nrosrun exercise1 controller.py\n```\n')
    (root / 'assignment2' / 'README.md').write_text(
        '## How to run\n```\nroslaunch exp_assignment2 gazebo_world.launch\n```\n')
    found = packages_.find(str(root))
    main = next(p for p in found if p.name == 'exp_assignment2')
    own = {p.name: p.path for p in found}
    got = resolve(main.path, main.name, 'a', {}, DOG, set(own) | {'stage_ros'},
                  reader({'gazebo_world.launch': ['/gazebo']}), root=str(root), packages=own,
                  other_parts=lambda entries, texts: assignment.other_sections(
                      texts, entries, found, main, str(root)))
    assert got['commands'] == ['roslaunch exp_assignment2 gazebo_world.launch']
    why = "left out: another part of the README (`Exercise 1` of README.md) starts " \
        "exercise1, stage_ros, not this assignment's exp_assignment2"
    assert commands_ran(got) == {
        'rosrun stage_ros stageros "$(rospack find exercise1)/world/exercise.world"': (
            False, why),
        'rosrun exercise1 controller.py': (False, why),
        'roslaunch exp_assignment2 gazebo_world.launch': (True, '')}


def test_a_readme_that_starts_nothing_runs_the_package_s_one_start_script(tmp_path):
    """The README's script only builds (catkin_make, chmod), though the README says it
    starts every terminal; the package's other script opens them: a person looking
    for how to start it runs that one, and Stage's line is the world's to replace."""
    files = {'Ass1.sh': 'cd ../..\ncatkin_make\nchmod +x scripts/*.py\n',
             'l.sh': 'gnome-terminal -x sh -c "roscore; bash"\n'
                     'gnome-terminal -x sh -c "rosrun stage_ros stageros world/a.world; bash"\n'
                     'gnome-terminal -x sh -c "rosrun my_pkg state_manager.py; bash"\n'
                     'roslaunch --wait my_pkg launch_all.launch\n',
             'scripts/state_manager.py': '', 'launch/launch_all.launch': '<launch/>'}
    root = package(tmp_path, '```sh\nchmod +x Ass1.sh\n./Ass1.sh\n```\nThis starts every '
                             'terminal.\n', files)
    miro = {'world_commands': ['roslaunch {sim} miro_world.launch'],
            'default_commands': ['rosrun {package} state_manager.py']}
    got = resolve(root, 'my_pkg', 'a', {}, miro, {'stage_ros'},
                  reader({'launch_all.launch': ['/grounding']}))
    assert got['commands'] == ['roslaunch exp_assignment2 miro_world.launch',
                               'rosrun my_pkg state_manager.py',
                               'roslaunch --wait my_pkg launch_all.launch']
    assert any("the package's one start script, l.sh, run as a person looking for how to "
               "start it does" in note for note in got['notes'])
    # two scripts that start nodes: which one a person would run cannot be told
    (tmp_path / 'my_pkg' / 'other.sh').write_text('rosrun my_pkg state_manager.py\n')
    got = resolve(root, 'my_pkg', 'a', {}, miro, {'stage_ros'}, reader({}))
    assert got['commands_from'] == "the profile's default after the profile's world"

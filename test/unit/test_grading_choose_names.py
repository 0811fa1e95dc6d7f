"""A name the package does not have, in a README (grading.plan.planning.resolve):
the one of its own close to it runs, and the page says so; near misses stay as
written; every package of a repository is looked in."""
import pytest

from exp_assignment2.grading.plan.planning import resolve
from readme_packages import DOG, commands_ran, package, reader

LAUNCHES = {'launch/pet_behavior.launch': '<launch/>', 'launch/gazebo_world.launch': '<launch/>',
            'launch/world1.launch': '<launch/>', 'launch/world2.launch': '<launch/>',
            'launch/bell.launch': '<launch/>', 'scripts/state_machine.py': '',
            'scripts/ball.py': ''}


@pytest.mark.parametrize('written, runs, why', [
    # a typo, a case difference, a node without its .py: the one own name close to it
    ('roslaunch my_pkg pet_beaviour.launch', 'roslaunch my_pkg pet_behavior.launch',
     "ran `pet_behavior.launch` for the README's `pet_beaviour.launch`"),
    ('rosrun my_pkg State_Machine.py', 'rosrun my_pkg state_machine.py',
     "ran `state_machine.py` for the README's `State_Machine.py`"),
    ('rosrun my_pkg state_machine', 'rosrun my_pkg state_machine.py',
     "ran `state_machine.py` for the README's `state_machine`"),
    # renamed and mistyped: both said
    ('roslaunch assignment2 gazebo_wrld.launch', 'roslaunch my_pkg gazebo_world.launch',
     "there is no package assignment2: runs the submission's own (package.xml names it "
     "my_pkg); ran `gazebo_world.launch` for the README's `gazebo_wrld.launch`"),
    # near misses that stay as written: two names as close, only an ending in common,
    # a name that is there, another package's file
    ('roslaunch my_pkg world.launch', 'roslaunch my_pkg world.launch', ''),
    ('roslaunch my_pkg ball.launch', 'roslaunch my_pkg ball.launch', ''),
    ('roslaunch my_pkg world1.launch', 'roslaunch my_pkg world1.launch', ''),
    ('rosrun my_pkg ball.py', 'rosrun my_pkg ball.py', ''),
    ('roslaunch gazebo_ros empty_wrld.launch', 'roslaunch gazebo_ros empty_wrld.launch', ''),
])
def test_a_name_the_package_does_not_have_runs_the_one_close_to_it(tmp_path, written, runs,
                                                                   why):
    root = package(tmp_path, '`%s`\n' % written, LAUNCHES)
    got = resolve(root, 'my_pkg', 'a', {}, DOG, {'gazebo_ros'}, lambda requests, packages: {
        r['key']: {'nodes': []} for r in requests})
    assert got['commands'] == [runs]
    (item,) = got['readme_commands']
    assert (item['ran'], item['why']) == (True, why)
    assert bool(item.get('corrected')) == bool(why)
    if why:
        assert got['notes'][0] == '`%s`: %s' % (written, item['why'])


def test_every_package_of_the_submission_is_looked_in(tmp_path):
    """A repository of two packages, its README at the root: a launch file
    named in the wrong one of them runs from the one that has it."""
    root = tmp_path / 'repo'
    for name in ('dog_pkg', 'dog_world'):
        (root / name / 'launch').mkdir(parents=True)
        (root / name / 'package.xml').write_text('<package><name>%s</name></package>' % name)
    (root / 'dog_world' / 'launch' / 'world.launch').write_text('<launch/>')
    (root / 'README.md').write_text('```\nroslaunch dog_pkg world.launch\n'
                                    'roslaunch dog_world world.launch\n```\n')
    packages = {'dog_pkg': str(root / 'dog_pkg'), 'dog_world': str(root / 'dog_world')}
    seen = []
    got = resolve(str(root / 'dog_pkg'), 'dog_pkg', 'a', {}, DOG, set(),
                  reader({'world.launch': ['/gazebo']}, seen), root=str(root),
                  packages=packages)
    assert got['commands'] == ['roslaunch dog_world world.launch']
    assert commands_ran(got)['roslaunch dog_pkg world.launch'] == (
        True, "dog_pkg has no world.launch: runs package dog_world's")
    assert commands_ran(got)['roslaunch dog_world world.launch'][1].startswith('left out: also starts')
    assert seen[0][1]['dog_world'] == packages['dog_world']

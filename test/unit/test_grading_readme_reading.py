"""A README as a person reads it: a ``cd`` before a command, a launch file
given by its path, build lines, the README at the root then the packages'
(exp_assignment2.grading.plan.commands, .planning)."""
import os

import pytest

from exp_assignment2.grading.plan.commands import readme_entries
from exp_assignment2.grading.plan.planning import resolve


def submission(tmp_path, readme, folders=('launch', 'scripts', 'src')):
    """my_pkg with a README, launch/gazebo_world.launch and some folders."""
    root = tmp_path / 'my_pkg'
    for folder in folders:
        (root / folder).mkdir(parents=True)
    (root / 'package.xml').write_text('<package><name>my_pkg</name></package>')
    (root / 'launch' / 'gazebo_world.launch').write_text('<launch/>')
    (root / 'README.md').write_text(readme)
    return str(root)


DOG = {'world_commands': [], 'default_commands': ['roslaunch {package} w.launch']}


def read_all(requests, packages):
    return {r['key']: {'nodes': ['/node%s' % r['key']]} for r in requests}


@pytest.mark.parametrize('readme, cwd', [
    ('Go to the folder: `cd launch`, then `roslaunch gazebo_world.launch`\n', 'launch'),
    ('```\ncd launch\n\nroslaunch gazebo_world.launch\n```\n', 'launch'),
    ('    cd ~/catkin_ws/src/my_pkg/launch && roslaunch gazebo_world.launch\n', 'launch'),
    ('    $ cd ~/catkin_ws/src/assignment_2/launch; roslaunch gazebo_world.launch\n', 'launch'),
    ('    roscd my_pkg/launch\n    roslaunch gazebo_world.launch\n', 'launch'),
    ('    cd scripts\n    cd ../launch\n    roslaunch gazebo_world.launch\n', 'launch'),
    ('    cd $(rospack find my_pkg)/launch\n    roslaunch gazebo_world.launch\n', 'launch'),
])
def test_a_cd_sets_the_folder_the_commands_after_it_run_from(tmp_path, readme, cwd):
    root = submission(tmp_path, readme)
    seen = []
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), lambda requests, packages: seen.extend(
        requests) or read_all(requests, packages))
    assert got['commands'] == ['roslaunch gazebo_world.launch'], got['notes']
    assert [(s['command'], s['cwd']) for s in got['starts']] == [
        ('roslaunch gazebo_world.launch', cwd)]
    assert seen[0]['path'] == os.path.join(root, 'launch', 'gazebo_world.launch')
    assert got['notes'] == [] and got['readme_commands'][0]['ran']


@pytest.mark.parametrize('target, cwd', [
    ('~/catkin_ws', ''), ('~', ''), ('~/catkin_ws/src', ''), ('..', ''), ('/etc', ''),
    ('../../..', ''), ('$HOME/catkin_ws/src/my_pkg/scripts', 'scripts'),
    ('~/catkin_ws/src/my_pkg/src', 'src'), ('nowhere', ''),
])
def test_a_cd_stays_inside_the_submission(tmp_path, target, cwd):
    root = submission(tmp_path, '    cd %s\n    rosrun my_pkg dog.py\n' % target)
    entries, _ = readme_entries(root, packages={'my_pkg': root})
    assert [(e['command'], e['cwd']) for e in entries] == [('rosrun my_pkg dog.py', cwd)]


def test_a_launch_file_by_path_that_is_elsewhere_runs_the_packages(tmp_path):
    root = submission(tmp_path, '`roslaunch gazebo_world.launch`\n')
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), read_all)
    assert got['commands'] == ['roslaunch my_pkg gazebo_world.launch']
    assert got['notes'] == ["`roslaunch gazebo_world.launch`: there is no gazebo_world.launch "
                            "in the submission's folder: runs package my_pkg's"]


BUILD_README = '''```
cd ~/catkin_ws && catkin_make --only-pkg-with-deps my_pkg
catkin build my_pkg other_course_pkg
catkin_make -DCATKIN_WHITELIST_PACKAGES="my_pkg;x"
rosdep install --from-paths src --ignore-src -y
chmod +x src/my_pkg/scripts/*.py
source devel/setup.bash
roslaunch my_pkg gazebo_world.launch
```
'''


def test_build_lines_are_build_steps_never_run(tmp_path):
    root = submission(tmp_path, BUILD_README)
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), read_all)
    assert got['commands'] == ['roslaunch my_pkg gazebo_world.launch']
    listed = got['readme_commands']
    assert [(c['kind'], c['ran']) for c in listed] == [('build', False)] * 6 + [('ros', True)]
    assert {c['why'] for c in listed[:6]} == {'a build step: the grader builds the submission '
                                             'itself'}
    assert got['build_packages'] == ['my_pkg'] and got['notes'] == []
    entries, _ = readme_entries(root)
    assert [e['packages'] for e in entries[:3]] == [
        ['my_pkg'], ['my_pkg', 'other_course_pkg'], ['my_pkg', 'x']]


def test_the_readme_at_the_root_then_the_packages(tmp_path):
    """A repository's README at its root comes first; the main package's
    follows when it says something else; the same text is read once."""
    root = tmp_path / 'repo'
    pkg = root / 'my_pkg'
    (pkg / 'launch').mkdir(parents=True)
    (pkg / 'package.xml').write_text('<package><name>my_pkg</name></package>')
    (root / 'README.md').write_text('`roslaunch my_pkg world.launch`\n')
    (pkg / 'README.md').write_text('`rosrun my_pkg dog.py`\n`roslaunch my_pkg world.launch`\n')
    entries, name = readme_entries(str(root), str(pkg))
    assert name == 'README.md and my_pkg/README.md'
    assert [(e['command'], e['from'], e['cwd']) for e in entries] == [
        ('roslaunch my_pkg world.launch', 'README.md', ''),
        ('rosrun my_pkg dog.py', 'my_pkg/README.md', 'my_pkg')]
    (pkg / 'README.md').write_text('`roslaunch my_pkg world.launch`\n')
    assert readme_entries(str(root), str(pkg))[1] == 'README.md'
    (root / 'README.md').unlink()
    assert readme_entries(str(root), str(pkg))[1] == 'my_pkg/README.md'


def test_a_build_lines_packages_are_built_and_said_so(tmp_path):
    """resolve's build_packages reach packages.choose: a package only a build
    line names is built for that reason; one the main package uses says so."""
    from exp_assignment2.grading.entry import packages
    manifest = '<package format="2"><name>%s</name><version>0.0.1</version>%s</package>'
    for name, depends in (('dog', '<depend>dog_msgs</depend>'), ('dog_msgs', ''),
                          ('dog_tools', '')):
        (tmp_path / name).mkdir()
        (tmp_path / name / 'package.xml').write_text(manifest % (name, depends))
    (tmp_path / 'README.md').write_text('    catkin build dog_msgs dog_tools\n'
                                        '    roslaunch dog world.launch\n')
    found = packages.find(str(tmp_path))
    own = {p.name: p.path for p in found}
    got = resolve(own['dog'], 'dog', 'a', {}, DOG, set(), read_all, root=str(tmp_path),
                  packages=own)
    assert got['build_packages'] == ['dog_msgs', 'dog_tools']
    main = next(p for p in found if p.name == 'dog')
    listed, _ = packages.choose(found, main, got['commands'], got['build_packages'])
    assert {p['name']: p['why'] for p in listed} == {
        'dog': 'built: the run is about it', 'dog_msgs': 'built: used by dog',
        'dog_tools': "built: the README's build line names it"}

"""How the grader starts a submission, and what a profile may say
(exp_assignment2.grading.plan.commands, .profiles)."""
import json
import os
import re

import pytest

from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.plan.commands import TeacherFileError, read_teacher_file, \
    readme_entries
from exp_assignment2.grading.plan.planning import resolve
from exp_assignment2.grading.plan.spec import RunSpec, settings

README = '''# My assignment

First build it, then in one shell:

```bash
$ roslaunch exp_assignment2 gazebo_world.launch   # the world
```

and in another `rosrun exp_assignment2 state_machine.py`, then watch it with
`rosrun rqt_image_view rqt_image_view` if you like. Use
`roslaunch <your_package> file.launch` for yours.

    cd ~/catkin_ws && source devel/setup.bash && roslaunch exp_assignment2 gazebo_world.launch
'''


def test_readme_commands_in_order_once(tmp_path):
    (tmp_path / 'README.md').write_text(README)
    entries, name = readme_entries(str(tmp_path))
    assert name == 'README.md'
    assert [(e['command'], e['kind']) for e in entries] == [
        ('roslaunch exp_assignment2 gazebo_world.launch', 'ros'),
        ('rosrun exp_assignment2 state_machine.py', 'ros'),
        ('rosrun rqt_image_view rqt_image_view', 'watch'),
        ('source devel/setup.bash', 'build')]


def no_launch_files(requests, packages):
    return {r['key']: {'error': 'not read in this test'} for r in requests}


def test_start_from_teacher_readme_or_profile(tmp_path):
    (tmp_path / 'README.md').write_text(README)
    profile = {'world_commands': [], 'default_commands': ['roslaunch {package} w.launch']}
    teacher = {'submissions': {'alice': {'commands': ['roslaunch a b.launch']}}}
    got = resolve(str(tmp_path), 'exp_assignment2', 'alice', teacher, profile, set(),
                  no_launch_files)
    assert (got['commands'], got['commands_from']) == (['roslaunch a b.launch'],
                                                       'grading.yaml (submissions: alice)')
    got = resolve(str(tmp_path), 'exp_assignment2', 'bob', teacher, profile, set(),
                  no_launch_files)
    assert got['commands_from'] == "the submission's README.md" and len(got['commands']) == 2
    assert [c['ran'] for c in got['readme_commands']] == [True, True, False, False]
    assert '`rosrun rqt_image_view rqt_image_view`: only watches' in got['notes'][-1]
    assert got['readme_commands'][-1]['why'] == 'a build step: the grader builds the ' \
        'submission itself'
    empty = tmp_path / 'empty'
    empty.mkdir()
    got = resolve(str(empty), 'my_pkg', 'carol', {}, profile, set(), no_launch_files)
    assert (got['commands'], got['commands_from']) == (['roslaunch my_pkg w.launch'],
                                                       "the profile's default")
    assert got['notes'] == ["no roslaunch or rosrun line to run in a README (there is none): "
                            "the profile's default"]


@pytest.mark.parametrize('text, message', [
    ('duraton: 10\n', "unknown key 'duraton' (did you mean 'duration'?)"),
    ('duration: ten\n', "duration: 'ten' is not a"),
    ('commands: [1]\n', 'commands: each must be a command line'),
    ('- a\n- b\n', 'must be a mapping of settings'),
    ('duration: [\n', 'not YAML'),
])
def test_a_teacher_file_with_a_typo_is_one_line(tmp_path, text, message):
    path = tmp_path / 'grading.yaml'
    path.write_text(text)
    with pytest.raises(TeacherFileError) as error:
        read_teacher_file(str(path))
    assert message in str(error.value) and '\n' not in str(error.value)


def test_the_two_profiles_load():
    dog, miro = profiles.load('dog'), profiles.load('miro')
    assert dog['robot'] == 'robot' and dog['ball'] == 'ball'
    assert [c['metric'] for c in dog['checks']] == [
        'approaches', 'first_approach_time', 'looks_both_ways', 'follows_ball', 'gives_up_ball',
        'sleeps', 'wanders', 'path_length', 'python_errors']
    assert dog['ball_script'] is None and dog['reach'] == 3.2      # the student's own ball
    assert miro['record_topics'] == ['/target_pos']
    course = profiles.load('dog_course')      # the dog's, on the course's ball (base: dog)
    assert course['ball'] == 'ball' and course['ball_script'] == {
        'seeds': [1], 'hidden': [], 'model': None}
    assert course['checks'] == dog['checks'] and course['name'] == 'dog_course'


def test_a_teachers_copy_with_a_changed_threshold(tmp_path):
    text = open(profiles.PROFILE_DIR + '/dog.yaml').read().replace('angle: 0.4 ', 'angle: 0.7 ')
    (tmp_path / 'strict.yaml').write_text(text)
    strict = profiles.load(str(tmp_path / 'strict.yaml'))
    assert [c['angle'] for c in strict['checks'] if c['metric'] == 'looks_both_ways'] == [0.7]


@pytest.mark.parametrize('change, message', [
    (('metric: path_length', 'metric: path_lenght'), "metric 'path_lenght' is not one of"),
    (('    leave: 2.0 ', '    leeve: 2.0 '), "unknown key 'leeve' (did you "
                                                           "mean 'leave'?)"),
    (('reach: 3.2 ', 'reach: -3 '), 'reach: -3 is not a positive distance in m'),
    (('home: null ', 'home: [1] '), 'home: [1] is not [x, y] in m'),
    (('ball: ball ', 'ball: {name: ball, script: {sed: 3}} '),
     "ball: script: unknown key 'sed' (known: seed, seeds, hidden, model)"),
    (('ball: ball ', 'ball: {name: ball, script: {seeds: [3], hidden: [4]}} '),
     "ball: script: hidden: [4]: a list of the script's seeds"),
    (('duration: 240', 'duration: -1'), 'duration: -1 is not a positive number'),
])
def test_a_broken_profile_is_one_line(tmp_path, change, message):
    text = open(profiles.PROFILE_DIR + '/dog.yaml').read().replace(*change)
    (tmp_path / 'p.yaml').write_text(text)
    with pytest.raises(profiles.ProfileError, match=re.escape(message)):
        profiles.load(str(tmp_path / 'p.yaml'))
    with pytest.raises(profiles.ProfileError, match="no profile 'cat'"):
        profiles.load('cat')


def test_a_typo_in_one_submissions_settings_costs_that_one_only(tmp_path):
    path = tmp_path / 'grading.yaml'
    path.write_text('submissions:\n  alice:\n    comands: [x]\n  bob:\n    skip: true\n')
    teacher = read_teacher_file(str(path))
    assert teacher['errors'] == {'alice': "grading.yaml: submissions: alice: unknown key "
                                          "'comands' (did you mean 'commands'?) (known: "
                                          "at, commands, commit, release, roles, skip)"}
    assert teacher['submissions'] == {'bob': {'skip': True}}


def test_the_teacher_names_one_submissions_roles(tmp_path):
    """roles: the robot, head or ball of one submission, as the teacher saw them;
    a wrong one costs that submission only."""
    path = tmp_path / 'grading.yaml'
    path.write_text('submissions:\n  alice:\n    roles: {robot: rover, head: neck_yaw}\n'
                    '  bob:\n    roles: {tail: wag}\n')
    teacher = read_teacher_file(str(path))
    assert teacher['submissions'] == {'alice': {'roles': {'robot': 'rover', 'head': 'neck_yaw'}}}
    assert teacher['errors']['bob'].startswith("grading.yaml: submissions: bob: roles: 'tail'")


PROFILE = {'name': 'dog', 'duration': 200, 'delay': 5}


@pytest.mark.parametrize('cli, teacher, expected', [
    ({}, {}, ('dog', 200.0, 1.0, 5)),
    ({}, {'profile': 'miro', 'duration': 60, 'real_time_factor': 2, 'delay': 3},
     ('miro', 60.0, 2.0, 3)),
    ({'profile': 'dog', 'duration': 30, 'real_time_factor': 4},
     {'profile': 'miro', 'duration': 60, 'real_time_factor': 2}, ('dog', 30.0, 4.0, 5)),
    ({'duration': 30}, {'real_time_factor': 2}, ('dog', 30.0, 2.0, 5)),
    ({'real_time_factor': 3}, {'duration': 90}, ('dog', 90.0, 3.0, 5)),
])
def test_command_line_over_grading_yaml_over_the_profile(cli, teacher, expected):
    profiles = {'dog': PROFILE, 'miro': dict(PROFILE, name='miro', duration=400, delay=7)}
    chosen, where = settings(dict(dict.fromkeys(['profile', 'duration', 'real_time_factor']),
                                  **cli), teacher, profiles.__getitem__)
    if expected[0] == 'miro' and 'delay' not in teacher:
        expected = expected[:3] + (7,)
    assert (chosen['profile']['name'], chosen['duration'], chosen['real_time_factor'],
            chosen['profile']['delay']) == expected
    assert where['duration'] == ('the command line' if 'duration' in cli else 'grading.yaml'
                                 if 'duration' in teacher else 'the profile')


def test_a_spec_goes_to_a_worker_as_plain_json():
    spec = RunSpec(name='ann', path='/class/ann.zip', kind='zip', seed=3, profile=PROFILE,
                   real_time_factor=2, hidden=['/class'], version='0.1.0',
                   commands=['roslaunch p w.launch'], commands_from="the submission's README.md",
                   readme_commands=[{'command': 'rqt_graph', 'ran': False, 'why': 'watches'}])
    assert spec.label == 'ann' and spec.duration == 200
    again = RunSpec.from_dict(json.loads(json.dumps(spec.to_dict())))
    assert again == spec and again.to_dict() == spec.to_dict()
    with pytest.raises(TypeError):
        RunSpec(name='x', start='what')


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
    from exp_assignment2.grading.plan import packages
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

"""How the grader starts a submission, and what a profile may say
(exp_assignment2.grading.plan.commands, .profiles)."""
import json
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
    (empty / 'launch').mkdir(parents=True)
    (empty / 'launch' / 'w.launch').write_text('<launch/>')
    got = resolve(str(empty), 'my_pkg', 'carol', {}, profile, set(), no_launch_files)
    assert (got['commands'], got['commands_from']) == (['roslaunch my_pkg w.launch'],
                                                       "the profile's default")
    assert got['notes'] == ["no roslaunch or rosrun line to run in a README (there is none): "
                            "the profile's default"]


def test_a_default_the_package_does_not_have_is_never_run(tmp_path):
    """The profile's default names w.launch; the package has its own launch files:
    the one that starts the rest (included by none, starting the simulator) runs in
    its place; with no such one, nothing runs, and the note says why."""
    profile = {'world_commands': [], 'default_commands': ['roslaunch {package} w.launch']}
    launch = tmp_path / 'launch'
    launch.mkdir()
    (launch / 'sim.launch').write_text(
        '<launch><include file="$(find gazebo_ros)/launch/empty_world.launch"/></launch>')
    (launch / 'everything.launch').write_text(
        '<launch><include file="$(find my_pkg)/launch/sim.launch"/><node pkg="my_pkg" '
        'type="dog.py" name="dog"/></launch>')
    (launch / 'nodes.launch').write_text('<launch><node pkg="my_pkg" type="b.py" name="b"/>'
                                         '</launch>')
    got = resolve(str(tmp_path), 'my_pkg', 'dan', {}, profile, set(), no_launch_files)
    assert got['commands'] == ['roslaunch my_pkg everything.launch']
    assert "my_pkg has no w.launch; ran its launch file that starts the rest, " \
        "`roslaunch my_pkg everything.launch`" in got['notes'][-1]
    (launch / 'everything.launch').unlink()
    (launch / 'other.launch').write_text(
        '<launch><include file="$(find gazebo_ros)/launch/empty_world.launch"/></launch>')
    got = resolve(str(tmp_path), 'my_pkg', 'dan', {}, profile, set(), no_launch_files)
    assert got['commands'] == [] and 'no one launch file of its own starts the rest ' \
        '(nodes.launch, other.launch, sim.launch): not run' in got['notes'][-1]


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

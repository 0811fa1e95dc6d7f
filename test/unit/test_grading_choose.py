"""A README read as a person reads it (exp_assignment2.grading.plan.choose,
.planning.resolve), the settings' one precedence and the run's specification
(.spec); launch files' nodes given by a fake reader, so no ROS and no master.
One test reads real launch files in the sandbox (launch_nodes.read)."""
import os
import shutil

import pytest

from exp_assignment2.grading.plan import launch_nodes
from exp_assignment2.grading.plan.planning import resolve
from readme_packages import DOG, MIRO, commands_ran, package, reader


def test_a_second_world_is_an_alternative_by_its_nodes(tmp_path):
    root = package(tmp_path, '```\nroslaunch my_pkg random.launch\n'
                             'roslaunch my_pkg fixed.launch\n```\n')
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader(
        {'random.launch': ['/gazebo', '/dog'], 'fixed.launch': ['/gazebo', '/dog']}))
    assert got['commands'] == ['roslaunch my_pkg random.launch']
    assert commands_ran(got)['roslaunch my_pkg fixed.launch'] == (
        False, 'left out: also starts /gazebo, an alternative to '
               '`roslaunch my_pkg random.launch`')
    assert got['notes'] == ['`roslaunch my_pkg fixed.launch`: left out: also starts /gazebo, '
                            'an alternative to `roslaunch my_pkg random.launch`']


def test_everything_then_the_same_nodes_in_two_terminals(tmp_path):
    root = package(tmp_path, 'Run `roslaunch my_pkg everything.launch`; alternatively, in two '
                             'terminals, `rosrun my_pkg dog.py` and `rosrun my_pkg ball.py`, '
                             'then `rosrun my_pkg dog.py __name:=dog2`.\n',
                   {'scripts/dog.py': "import rospy\nrospy.init_node('dog')\n",
                    'scripts/ball.py': 'import rospy\nrospy.init_node("ball_mover", '
                                       'disable_signals=True)\n'})
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader(
        {'everything.launch': ['/gazebo', '/dog', '/ball_mover']}))
    assert got['commands'] == ['roslaunch my_pkg everything.launch',
                               'rosrun my_pkg dog.py __name:=dog2']
    assert commands_ran(got)['rosrun my_pkg dog.py'][1].startswith('left out: also starts /dog, an ')
    assert commands_ran(got)['rosrun my_pkg ball.py'][1].startswith('left out: also starts /ball_mover')


def test_a_cpp_node_is_named_by_its_ros_init(tmp_path):
    root = package(tmp_path, '    rosrun my_pkg counter\n    rosrun my_pkg counter2\n', {
        'CMakeLists.txt': 'add_executable(counter src/c.cpp)\nadd_executable(counter2 src/d.cpp)\n',
        'src/c.cpp': 'int main(int c, char** v) { ros::init(c, v, "counter"); }',
        'src/d.cpp': 'int main(int c, char** v) { ros::init(c, v, "counter"); }'})
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader({}))
    assert got['commands'] == ['rosrun my_pkg counter']


def test_a_readme_naming_another_package_runs_the_submissions_own(tmp_path):
    root = package(tmp_path, '```\nroslaunch assignment2 gazebo_world.launch\n'
                             'rosrun assignment2 dog.py\nrosrun gazebo_ros spawn_model x\n```\n',
                   {'launch/gazebo_world.launch': '<launch/>', 'scripts/dog.py': ''})
    seen = []
    got = resolve(root, 'my_pkg', 'a', {}, DOG, {'gazebo_ros'},
                  reader({'gazebo_world.launch': ['/gazebo']}, seen))
    assert got['commands'] == ['roslaunch my_pkg gazebo_world.launch', 'rosrun my_pkg dog.py',
                               'rosrun gazebo_ros spawn_model x']
    assert commands_ran(got)['roslaunch assignment2 gazebo_world.launch'] == (
        True, "there is no package assignment2: runs the submission's own (package.xml "
              "names it my_pkg)")
    # $(find assignment2) in its launch files is the submission too
    assert seen[0][1]['assignment2'] == root and seen[0][1]['my_pkg'] == root


def test_a_package_missing_everywhere_stays_as_written(tmp_path):
    root = package(tmp_path, '`roslaunch other_pkg world.launch`\n')
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader({}))
    assert got['commands'] == ['roslaunch other_pkg world.launch']


def test_commands_that_only_watch_are_left_out(tmp_path):
    root = package(tmp_path, '```\n$ roslaunch my_pkg w.launch\n$ rostopic echo /odom\n'
                             'rqt_graph\nrosrun rviz rviz\nrosnode list | grep dog\n'
                             'rostopic hz /camera/image_raw\n```\n')
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader({'w.launch': ['/gazebo']}))
    assert got['commands'] == ['roslaunch my_pkg w.launch']
    assert [c['ran'] for c in got['readme_commands']] == [True] + [False] * 5
    assert set(commands_ran(got)['rqt_graph']) == {
        False, 'only watches (a command for another shell): left out'}


RUN_SH = '''#!/bin/bash
# start everything, each in its terminal
gnome-terminal -x sh -c "rosrun stage_ros stageros $(rospack find my_pkg)/w.world; bash"
sleep 2
gnome-terminal -x sh -c "rosrun my_pkg state_manager.py; bash"
xterm -e 'roslaunch my_pkg miro.launch' &
'''


def test_a_start_script_is_read_for_its_commands(tmp_path):
    root = package(tmp_path, 'Start it with `./run.sh`\n', {'run.sh': RUN_SH})
    got = resolve(root, 'my_pkg', 'a', {}, MIRO, set(), reader({'miro.launch': ['/miro']}))
    assert got['commands'] == ['roslaunch exp_assignment2 miro_world.launch',
                               'rosrun my_pkg state_manager.py',
                               'roslaunch my_pkg miro.launch']
    assert got['commands_from'] == "the submission's README.md after the profile's world"
    listed = got['readme_commands']
    assert listed[0] == {'command': './run.sh', 'ran': False, 'kind': 'script',
                         'why': 'a start script: its roslaunch/rosrun lines are read, not the '
                                'script run'}
    assert listed[1] == {'command': 'rosrun stage_ros stageros $(rospack find my_pkg)/w.world',
                         'ran': False, 'from': 'run.sh', 'kind': 'ros',
                         'why': "a simulator the profile's world replaces: left out"}
    assert [c['ran'] for c in listed[2:]] == [True, True]


def test_without_a_world_in_the_profile_the_students_simulator_runs(tmp_path):
    root = package(tmp_path, '`bash run.sh`\n', {'run.sh': RUN_SH})
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader({'miro.launch': ['/miro']}))
    assert got['commands'][0].startswith('rosrun stage_ros stageros')


def test_an_unreadable_launch_file_runs_and_is_said(tmp_path):
    root = package(tmp_path, '`roslaunch my_pkg broken.launch`\n')
    got = resolve(root, 'my_pkg', 'a', {}, DOG, set(), reader({}))
    assert got['commands'] == ['roslaunch my_pkg broken.launch']
    assert got['notes'] == ['`roslaunch my_pkg broken.launch`: its launch file was not read '
                            '(XmlParseException: bad): run, not compared with the others']


def test_package_and_sim_are_put_in_every_command(tmp_path):
    root = package(tmp_path, 'nothing to run\n')
    got = resolve(root, 'exp_assignment2', 'a', {'commands': ['roslaunch {sim} x.launch',
                                                              'rosrun {package} y.py']},
                  MIRO, set(), reader({}))
    assert got['commands'] == ['roslaunch exp_assignment2_sim miro_world.launch',
                               'roslaunch exp_assignment2_sim x.launch',
                               'rosrun exp_assignment2 y.py']


EVAL = '''<launch><arg name="x" value="$(eval open('{marker}2', 'w').write('x') or 1)"/>
  <node name="x" pkg="my_pkg" type="x.py"/></launch>'''
LAUNCH = '''<launch>
  <param name="pwned" command="touch {marker}"/>
  <include file="$(find assignment2)/launch/inner.launch"/>
  <group ns="robot"><node name="dog" pkg="my_pkg" type="dog.py"/></group>
</launch>
'''


@pytest.mark.skipif(not shutil.which('bwrap'), reason='needs bubblewrap')
def test_launch_files_are_read_by_roslaunch_in_a_sandbox(tmp_path):
    pytest.importorskip('roslaunch')
    marker = tmp_path / 'outside' / 'marker'
    marker.parent.mkdir()
    root = package(tmp_path, '', {
        'launch/world.launch': LAUNCH.format(marker=marker),
        'launch/eval.launch': EVAL.format(marker=marker),
        'launch/inner.launch': '<launch><node name="gazebo" pkg="gazebo_ros" type="gzserver"/>'
                               '</launch>',
        # what the reader may do: its capabilities, in its node's name
        'launch/caps.launch': ("<launch><node name=\"$(eval 'c' + open('/proc/self/status')"
                               ".read().split('CapEff:')[1].split()[0])\" pkg='x' type='y'/>"
                               "</launch>")})
    got = launch_nodes.read({'launches': [
        {'key': '0', 'package': 'my_pkg', 'file': 'world.launch', 'args': []},
        {'key': '1', 'package': 'my_pkg', 'file': 'none.launch'},
        {'key': '2', 'package': 'my_pkg', 'file': 'eval.launch'},
        {'key': '3', 'package': 'my_pkg', 'file': 'caps.launch'}],
        'packages': {'my_pkg': root, 'assignment2': root}}, shown=[root],
        hidden=[str(marker.parent)])
    assert got['0'] == {'nodes': ['/gazebo', '/robot/dog']}
    assert got['1']['error'].startswith('OSError: my_pkg has no none.launch')
    assert got['2'] == {'nodes': ['/x']}    # its eval ran in the sandbox: what it wrote is gone
    assert os.listdir(str(marker.parent)) == []      # nothing it ran wrote here
    assert got['3'] == {'nodes': ['/c0000000000000000']}     # no capability (bwrap keeps root's)


def test_the_plan_reads_an_archive_on_the_teachers_side(tmp_path, monkeypatch):
    """A zipped submission's README is read before any run; grading.yaml's
    settings hold where the command line gives none; a mistake in one
    submission's settings is carried in its spec, not patched onto a run."""
    import argparse
    import zipfile
    from exp_assignment2.grading.entry import build_deps
    from exp_assignment2.grading.plan import planning
    from exp_assignment2.grading.entry.copies import Copies
    monkeypatch.setattr(build_deps, 'available_debian', lambda: set())
    monkeypatch.setattr(build_deps, 'install', lambda names, log: None)
    monkeypatch.setattr(launch_nodes, 'provided_packages', lambda: {'gazebo_ros'})
    monkeypatch.setattr(launch_nodes, 'read', lambda request, **kw: {
        r['key']: {'nodes': ['/gazebo']} for r in request['launches']})
    root = package(tmp_path, '`roslaunch my_pkg a.launch` or `roslaunch my_pkg b.launch`\n')
    folder = tmp_path / 'class'
    folder.mkdir()
    with zipfile.ZipFile(str(folder / 'ann.zip'), 'w') as archive:
        for name in os.listdir(root):
            archive.write(os.path.join(root, name), 'my_pkg/' + name)
    (folder / 'grading.yaml').write_text('duration: 50\nsubmissions:\n  ann:\n    skipp: true\n')
    args = argparse.Namespace(submissions=str(folder), profile=None, duration=None,
                              real_time_factor=3.0, only=None, repeat=1, seed=1)
    with Copies() as copies:
        specs, profile, where = planning.plan(args, str(tmp_path / 'out'), '0.1', print,
                                              planning.read_settings(args),
                                              planning.entries(args, print), copies)
    (spec,) = specs
    assert (spec.kind, spec.package, spec.commands) == ('zip', 'my_pkg',
                                                       ['roslaunch my_pkg a.launch'])
    assert (spec.duration, spec.real_time_factor, profile['name']) == (50.0, 3.0, 'dog')
    assert where == {'profile': 'the default', 'duration': 'grading.yaml',
                     'real_time_factor': 'the command line', 'delay': 'the profile'}
    assert "unknown key 'skipp'" in spec.refused
    (folder / 'grading.yaml').write_text('with: [../course_pkg]\n')
    with pytest.raises(planning.TeacherFileError, match='with: is not supported'), \
            Copies() as copies:
        planning.plan(args, str(tmp_path / 'out'), '0.1', print, planning.read_settings(args),
                      [], copies)

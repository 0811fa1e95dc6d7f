"""The Gazebo launch surface's command lines, read without ROS: spawn_model,
controller_manager's spawner, xacro; and the packages installed (gzserver's:
test_launch_surface_gzserver.py; what gzclient shows:
test_launch_surface_viewer.py).
"""
import math
import os
import shutil
import subprocess

import pytest

from exp_assignment2.launch_surface import spawn_args, spawner_args
from exp_assignment2.launch_surface.xacro_runner import xacro_argv

from exp_assignment2.original_env import launch_packages

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LIBRARY = os.path.join(REPO, 'src')      # where the stand-ins import the library from
PACKAGES = launch_packages.PACKAGES
STUDENT = os.path.join(REPO, 'test', 'fixtures', 'student_pkg')


# spawn_model

def test_spawn_model_reads_the_courses_command_line():
    o = spawn_args.parse('-urdf -model robot -param robot_description -x -5 -y 7 -Y 3.14 '
                         '-z 0.05'.split())
    assert (o.format, o.source, o.source_value, o.model) == ('urdf', 'param',
                                                              'robot_description', 'robot')
    assert o.pose == (-5, 7, 0.05, 0, 0, 3.14)
    assert (o.robot_namespace, o.gazebo_namespace, o.reference_frame) == (None, '/gazebo', '')
    assert (o.timeout, o.joints, o.unpause, o.wait, o.bond) == (60.0, [], False, None, False)


def test_spawn_model_every_option():
    o = spawn_args.parse(['-sdf', '-file', 'm.sdf', '-model', 'm', '-J', 'joint_head', '0.5',
                          '-J', 'arm', '-1e-3', '-reference_frame', 'table::link',
                          '-robot_namespace', '/bot', '-gazebo_namespace', '/sim/', '-unpause',
                          '-wait', 'table', '-timeout', '5', '-package_to_model', '-b',
                          '-R', '0.1', '-P', '-0.2'])
    assert (o.format, o.source, o.source_value) == ('sdf', 'file', 'm.sdf')
    assert o.joints == [('joint_head', 0.5), ('arm', -0.001)]
    assert (o.reference_frame, o.robot_namespace, o.gazebo_namespace) == ('table::link', '/bot',
                                                                           '/sim')
    assert (o.unpause, o.wait, o.timeout, o.package_to_model, o.bond) == (True, 'table', 5.0,
                                                                          True, True)
    assert o.pose == (0, 0, 0, 0.1, -0.2, 0)
    assert spawn_args.parse(['-urdf', '-stdin', '-model', 'm']).source == 'stdin'
    assert spawn_args.parse(['-sdf', '-database', 'jersey_barrier', '-model', 'm']).source_value \
        == 'jersey_barrier'


@pytest.mark.parametrize('argv,message', [
    ('-model a -param p', 'spawn_model: -urdf or -sdf is required'),
    ('-urdf -model a', 'spawn_model: -file, -param, -database or -stdin is required'),
    ('-urdf -param p', 'spawn_model: -model NAME is required'),
    ('-urdf -sdf -model a -param p', 'spawn_model: -urdf and -sdf cannot both be given'),
    ('-urdf -model a -file f -param p', 'spawn_model: -file and -param cannot both be given'),
    ('-urdf -model a -param p -x nan', "spawn_model: -x must be a finite number, not 'nan'"),
    ('-urdf -model a -param p -Y east', "spawn_model: -Y must be a finite number, not 'east'"),
    ('-urdf -model a -param p -J j inf', "spawn_model: -J j must be a finite number, not 'inf'"),
    ('-urdf -model a -param p -J j', 'spawn_model: -J j needs a value'),
    ('-urdf -model a -param', 'spawn_model: -param needs a value'),
    ('-urdf -model a -param p -timeout -1', 'spawn_model: -timeout must be positive, not -1'),
    ('-urdf -model a -param p -xyz 1', "spawn_model: unknown argument '-xyz' (spawn_model of "
                                       "ROS noetic refuses it: unrecognized arguments)"),
    ('-urdf -model a -param p extra', "spawn_model: unknown argument 'extra'"),
])
def test_spawn_model_refuses_bad_command_lines(argv, message):
    with pytest.raises(spawn_args.UsageError) as err:
        spawn_args.parse(argv.split())
    assert str(err.value).startswith(message)


def test_spawn_model_reads_as_each_release_did():
    """An option given twice takes its last value in every release; Kinetic's
    spawn_model ignored what it did not know, Melodic's argparse refuses it."""
    argv = '-urdf -model a -param p -x 1 -x 2 -model b -urdf -timeout_s 3'.split()
    o = spawn_args.parse(argv, 'kinetic')
    assert (o.pose[0], o.model, o.ignored) == (2.0, 'b', ['-timeout_s', '3'])
    with pytest.raises(spawn_args.UsageError, match="unknown argument '-timeout_s' "
                                                    r"\(spawn_model of ROS melodic"):
        spawn_args.parse(argv, 'melodic')
    assert spawn_args.parse(argv[:-2], 'noetic').pose[0] == 2.0


def test_spawn_model_quaternion_is_tfs_quaternion_from_euler():
    assert spawn_args.quaternion(0, 0, 0) == (0, 0, 0, 1)
    x, y, z, w = spawn_args.quaternion(0, 0, 3.14)
    assert (x, y) == (0, 0) and z == pytest.approx(math.sin(1.57)) and w == pytest.approx(
        math.cos(1.57))
    # roll then pitch then yaw about fixed axes: 90 deg roll, 90 deg yaw
    assert spawn_args.quaternion(math.pi / 2, 0, math.pi / 2) == pytest.approx((0.5, 0.5, 0.5,
                                                                                 0.5))


def test_spawn_model_xml_helpers():
    assert 'model://jersey_barrier' in spawn_args.database_xml('jersey_barrier')
    text = '<robot name="r"><link name="l"><visual><geometry><mesh ' \
           'filename="package://pkg/meshes/a.stl"/></geometry></visual></link></robot>'
    assert spawn_args.checked_xml(text) == text
    assert 'model://pkg/meshes/a.stl' in spawn_args.checked_xml(text, package_to_model=True)
    with pytest.raises(ValueError) as err:
        spawn_args.checked_xml('<robot>')
    assert str(err.value).startswith('Invalid XML: no element found')


# controller_manager spawner

def test_spawner_reads_the_courses_command_line():
    # args="--namespace=/robot joint_state_controller joint_position_controller
    #       --shutdown-timeout 3", split by roslaunch
    o = spawner_args.parse(['--namespace=/robot', 'joint_state_controller',
                            'joint_position_controller', '--shutdown-timeout', '3'])
    assert o == spawner_args.SpawnerOptions(['joint_state_controller',
                                             'joint_position_controller'], '/robot', False, None,
                                            30.0, 3.0)
    o = spawner_args.parse(['--stopped', '--wait-for', 'calibrated', '--no-timeout', 'a'])
    assert (o.stopped, o.wait_for, o.timeout, o.shutdown_timeout) == (True, 'calibrated', None,
                                                                      2.0)
    assert spawner_args.parse(['--timeout=5', 'a']).timeout == 5.0
    # argparse takes a unique prefix of a long option
    o = spawner_args.parse(['--name=/robot', '--stop', '--shutdown', '3', 'a'])
    assert (o.namespace, o.stopped, o.shutdown_timeout) == ('/robot', True, 3.0)


@pytest.mark.parametrize('argv,message', [
    ([], 'spawner: name at least one controller'),
    (['--namespace'], 'spawner: --namespace needs a value'),
    (['--timeout', 'soon', 'a'], "spawner: --timeout must be a positive number of seconds, not "
                                 "'soon'"),
    (['--shutdown-timeout=-2', 'a'], 'spawner: --shutdown-timeout must be a positive number'),
    (['--stopped=yes', 'a'], 'spawner: --stopped takes no value'),
    (['-v', 'a'], "spawner: unknown option '-v'"),
])
def test_spawner_refuses_bad_command_lines(argv, message):
    with pytest.raises(spawner_args.UsageError) as err:
        spawner_args.parse(argv)
    assert str(err.value).startswith(message)


@pytest.mark.parametrize('namespace,node_ns,expected', [
    ('/robot', '/', '/robot'), ('/robot/', '/x/', '/robot'), ('robot', '/', '/robot'),
    ('arm', '/robot/', '/robot/arm'), ('', '/robot/', '/robot'), ('', '/', '/'),
])
def test_spawner_finds_the_controller_manager_as_rospy_resolves_names(namespace, node_ns,
                                                                      expected):
    assert spawner_args.manager_namespace(namespace, node_ns) == expected


def test_spawner_service_names():
    assert spawner_args.service_names('/robot') == (
        '/robot/controller_manager/load_controller', '/robot/controller_manager/switch_controller',
        '/robot/controller_manager/unload_controller')
    assert spawner_args.service_names('/')[0] == '/controller_manager/load_controller'


# xacro

def test_xacro_drops_inorder_only():
    assert xacro_argv(['--inorder', 'a.xacro', 'ns:=x', '-o', 'out']) == ['a.xacro', 'ns:=x',
                                                                          '-o', 'out']
    assert xacro_argv(['-i', 'a.xacro']) == ['a.xacro']


def test_xacro_runs_the_students_robot_with_find_resolved(tmp_path):
    """Runs the stand-in executable as roslaunch's command= runs it; needs PyPI's
    xacro, which tools/run original-env installs."""
    check = subprocess.run(['/usr/bin/python3', '-c', 'import xacro'], stderr=subprocess.PIPE)
    if check.returncode != 0:
        pytest.skip('xacro not installed for /usr/bin/python3 (tools/run original-env '
                    'installs it)')
    # the fixture is a package named exp_assignment2: $(find exp_assignment2) must give it
    # (alone on the path: test/fixtures may hold other packages of that name)
    os.symlink(STUDENT, str(tmp_path / 'exp_assignment2'))
    env = dict(os.environ, ROS_PACKAGE_PATH=str(tmp_path), EXP2_LIBRARY=LIBRARY)
    proc = subprocess.run(['/usr/bin/python3', os.path.join(PACKAGES, 'xacro', 'xacro'),
                           '--inorder',
                           os.path.join(STUDENT, 'urdf', 'robot.xacro')], env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == ''            # no deprecation warning for --inorder
    urdf = proc.stdout
    assert 'libgazebo_ros_diff_drive.so' in urdf and 'libgazebo_ros_control.so' in urdf
    assert '<width>320</width>' in urdf and '<update_rate>15' in urdf
    assert '${' not in urdf and 'xacro:' not in urdf.replace('xmlns:xacro', '')


def test_xacro_reads_yaml_as_noetics_does(tmp_path):
    """load_yaml under Debian's PyYAML 6 (1.13's own passes no loader): dotted
    access, !degrees and !radians, and a missing key named."""
    if subprocess.run(['/usr/bin/python3', '-c', 'import xacro']).returncode != 0:
        pytest.skip('xacro not installed for /usr/bin/python3 (tools/run original-env '
                    'installs it)')
    (tmp_path / 'dims.yaml').write_text('chassis: {mass: 5.0, size: [0.5, 0.3]}\n'
                                        'neck: {upper: !degrees 45, lower: !radians -pi/4}\n')
    robot = tmp_path / 'robot.xacro'

    def run(upper):
        robot.write_text(
            '<robot name="dog" xmlns:xacro="http://www.ros.org/wiki/xacro">'
            '<xacro:property name="dims" value="${load_yaml(\'dims.yaml\')}"/>'
            '<link name="chassis"><inertial><mass value="${dims[\'chassis\'][\'mass\']}"/>'
            '<origin xyz="${dims.chassis.size[0]} 0 0"/></inertial></link>'
            '<joint name="neck" type="revolute"><parent link="chassis"/><child link="head"/>'
            '<limit upper="${%s}" lower="${dims.neck.lower}" effort="1" velocity="1"/>'
            '</joint><link name="head"/></robot>' % upper)
        return subprocess.run(['/usr/bin/python3', os.path.join(PACKAGES, 'xacro', 'xacro'),
                               str(robot)], env=dict(os.environ, EXP2_LIBRARY=LIBRARY),
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True, timeout=60)
    proc = run('dims.neck.upper')
    assert proc.returncode == 0, proc.stderr
    assert '<mass value="5.0"/>' in proc.stdout and '<origin xyz="0.5 0 0"/>' in proc.stdout
    assert 'lower="-0.785398163397' in proc.stdout and 'upper="0.785398163397' in proc.stdout
    proc = run('dims.neck.nope')
    assert proc.returncode != 0 and "No such key: 'nope'" in proc.stderr


def test_the_packages_are_installed_executable_once_per_content(tmp_path):
    source = tmp_path / 'source'
    shutil.copytree(PACKAGES, str(source))
    ws = tmp_path / 'ws'
    first = launch_packages.install(str(ws), str(source))
    assert first.startswith(str(ws / 'original_env_packages'))
    for path in launch_packages.EXECUTABLES + ('xacro/xacro.py',):
        assert os.access(os.path.join(first, path), os.X_OK), path
    assert os.path.isfile(os.path.join(first, 'gazebo_ros', 'launch', 'empty_world.launch'))
    # a display launch file's $(find urdf_tutorial)/urdf.rviz (a real class's): there
    # where Debian has no urdf_tutorial
    if not launch_packages.installed('urdf_tutorial'):
        assert 'Class: rviz/RobotModel' in open(os.path.join(
            first, 'urdf_tutorial', 'urdf.rviz')).read()
    assert launch_packages.install(str(ws), str(source)) == first
    (source / 'xacro' / 'xacro').write_text('#!/usr/bin/python3\n')
    second = launch_packages.install(str(ws), str(source))
    assert second != first and os.path.isdir(first)     # a running shell keeps its copy
    assert sorted(os.listdir(str(ws / 'original_env_packages'))) == sorted(
        [os.path.basename(first), os.path.basename(second)])    # no scratch left behind

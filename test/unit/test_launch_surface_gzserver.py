"""gzserver's command line read as Gazebo's Server::ParseArgs reads it, and
turned into the simulator's (no ROS): the world, -u, options Gazebo ignores
or refuses, and the drives' hold students' launch files get (cmd_timeout 0).
"""
import json

import pytest

from exp_assignment2.launch_surface import gzserver


def test_gzserver_reads_a_launch_files_command_line(tmp_path):
    world = tmp_path / 'arena.world'
    world.write_text('<sdf/>')
    # what empty_world.launch-style files give: -u, --verbose, -e ode, the world, ROS args
    cmd = gzserver.translate(['-u', '--verbose', '-e', 'ode', str(world), '__name:=gazebo',
                              '__log:=/tmp/gazebo-1.log'])
    assert cmd == gzserver.ServerCommand(str(world), True, True, [],
                                         ['__name:=gazebo', '__log:=/tmp/gazebo-1.log'])
    assert gzserver.simulator_argv(cmd, scripts='/r/lib') == [
        '/usr/bin/python3', '/r/lib/simulator.py', '_cmd_timeout:=0', '__name:=gazebo',
        '__log:=/tmp/gazebo-1.log', '_world_file:=%s' % json.dumps(str(world)), '_paused:=true']


def test_gzserver_empty_world_and_gazebo_resource_path(tmp_path):
    assert gzserver.translate(['-e', 'ode', 'worlds/empty.world']).world is None
    assert gzserver.translate([]).world is None
    (tmp_path / 'worlds').mkdir()
    (tmp_path / 'worlds' / 'cafe.world').write_text('<sdf/>')
    cmd = gzserver.translate(['worlds/cafe.world'],
                             {'GAZEBO_RESOURCE_PATH': '/nowhere:%s' % tmp_path})
    assert cmd.world == str(tmp_path / 'worlds' / 'cafe.world')
    assert gzserver.simulator_argv(cmd, '/r')[-1] == '_world_file:=%s' % json.dumps(cmd.world)
    assert gzserver.simulator_argv(gzserver.translate([]), '/r')[-1] == '_world_file:=""'


def test_gzserver_says_what_it_ignores():
    cmd = gzserver.translate(['-r', '--seed', '3', '-s', 'libgazebo_ros_api_plugin.so',
                              '--server-plugin=libfoo.so', '--physics=bullet'])
    assert cmd.notes == [
        'gzserver: -r ignored: runs are not recorded (use rosbag)',
        'gzserver: --seed 3 ignored: the simulator has no random elements to seed',
        'gzserver: server plugin libfoo.so is not available here: ignored']
    assert not cmd.paused and not cmd.verbose


def test_gzserver_ignores_what_gazebo_ignores(tmp_path):
    """Server::ParseArgs allows unregistered options, and words after the world
    file are "pass_through" for system plugins."""
    world = tmp_path / 'arena.world'
    world.write_text('<sdf/>')
    cmd = gzserver.translate(['--fast', str(world), 'worlds/empty.world', '-x'])
    assert cmd.world == str(world)
    assert cmd.notes == [
        "gzserver: unknown option '--fast' ignored (as Gazebo ignores options it does not know)",
        "gzserver: unknown option '-x' ignored (as Gazebo ignores options it does not know)",
        'gzserver: worlds/empty.world after the world file ignored (Gazebo passes them through '
        'to system plugins)']


@pytest.mark.parametrize('argv,message', [
    (['-e', 'physx'], "gzserver: unknown physics engine 'physx'; accepted: ode, bullet, "
                      "simbody, dart"),
    (['-e'], 'gzserver: -e needs a value'),
    (['/no/such.world'], "gzserver: world file '/no/such.world' not found (nor under "
                         "GAZEBO_RESOURCE_PATH='')"),
    (['-p', 'state.log'], 'gzserver: -p (playing a Gazebo log) is not supported'),
])
def test_gzserver_refuses_what_it_cannot_run(argv, message):
    with pytest.raises(gzserver.UsageError) as err:
        gzserver.translate(argv, {})
    assert str(err.value).startswith(message)

#!/usr/bin/env python3
"""What test/launch_surface.test's nodes asked of the simulator's Gazebo API
(the fake's recorded calls), and what the stand-ins do on their own: exit
codes and lines of spawn_model, the spawner's unloading when stopped,
gzclient without a display, gzserver's refusals, empty_world.launch's
arguments. Runs inside tools/run original-env (rospack finds the stand-ins).
"""
import json
import math
import os
import signal
import subprocess
import threading
import time
import unittest

import rospkg
import rospy
import rosnode
import rostest
from std_msgs.msg import String

WAIT = 60.0     # wall s for what the launch started to have happened


class Calls(object):
    """The fake Gazebo's recorded calls, as they come."""

    def __init__(self):
        self.calls, self.changed = [], threading.Condition()
        rospy.Subscriber('/fake_gazebo/calls', String, self._on_calls)

    def _on_calls(self, msg):
        with self.changed:
            self.calls = json.loads(msg.data)
            self.changed.notify_all()

    def wait_for(self, predicate, timeout=WAIT):
        """The first recorded call for which ``predicate`` holds."""
        deadline = time.monotonic() + timeout
        with self.changed:
            while True:
                found = [c for c in self.calls if predicate(c)]
                left = deadline - time.monotonic()
                if found or left <= 0:
                    return found[0] if found else None
                self.changed.wait(left)

    def of(self, service):
        with self.changed:
            return [c['request'] for c in self.calls if c['service'] == service]


def run(argv, timeout=30):
    """Run a stand-in executable; (exit status, stdout + stderr)."""
    proc = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=timeout)
    return proc.returncode, proc.stdout


class LaunchSurfaceTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('check_launch_surface')
        cls.calls = Calls()
        pack = rospkg.RosPack()
        cls.spawn_model = os.path.join(pack.get_path('gazebo_ros'), 'scripts', 'spawn_model')
        cls.gzserver = os.path.join(pack.get_path('gazebo_ros'), 'scripts', 'gzserver')
        cls.gzclient = os.path.join(pack.get_path('gazebo_ros'), 'scripts', 'gzclient')
        cls.spawner = os.path.join(pack.get_path('controller_manager'), 'scripts', 'spawner')

    def test_spawn_model_sends_the_xacro_urdf_where_the_launch_says(self):
        call = self.calls.wait_for(lambda c: c['service'] == 'spawn_urdf_model')
        self.assertIsNotNone(call, 'spawn_model never called /gazebo/spawn_urdf_model')
        req = call['request']
        self.assertEqual(req['model_name'], 'robot')
        self.assertEqual(req['robot_namespace'], '/robot/')    # the node's namespace
        self.assertEqual(req['reference_frame'], '')
        x, y, z, qx, qy, qz, qw = req['initial_pose']
        self.assertEqual((x, y, z), (1.5, -2.0, 0.05))
        self.assertAlmostEqual(2 * math.atan2(qz, qw), 1.2, places=6)
        self.assertEqual((qx, qy), (0.0, 0.0))
        # xacro did its work: macros expanded, the $(find) include brought the plugin
        self.assertIn('libgazebo_ros_control.so', req['model_xml'])
        self.assertIn('<box size="0.1 0.1 0.1"/>', req['model_xml'])
        self.assertNotIn('xacro:', req['model_xml'].replace('xmlns:xacro', ''))
        # then -J and -unpause, in that order
        self.assertIsNotNone(self.calls.wait_for(lambda c: c['service'] == 'unpause_physics'))
        order = [c['service'] for c in self.calls.calls]
        configure = self.calls.of('set_model_configuration')
        self.assertEqual(configure, [{'model_name': 'robot', 'urdf_param_name': '',
                                      'joint_names': ['joint_head'], 'joint_positions': [0.3]}])
        self.assertLess(order.index('spawn_urdf_model'), order.index('set_model_configuration'))
        self.assertLess(order.index('set_model_configuration'), order.index('unpause_physics'))

    def test_spawn_model_sends_an_sdf_file(self):
        call = self.calls.wait_for(lambda c: c['service'] == 'spawn_sdf_model')
        self.assertIsNotNone(call, 'spawn_model never called /gazebo/spawn_sdf_model')
        req = call['request']
        self.assertEqual((req['model_name'], req['robot_namespace']), ('crate', '/'))
        self.assertEqual(req['initial_pose'][:3], [3.0, 1.0, 0.2])
        self.assertIn('<model name="crate">', req['model_xml'])

    def test_spawner_loads_then_starts_the_yamls_controllers(self):
        ns = '/robot/controller_manager/'
        switch = self.calls.wait_for(lambda c: c['service'] == ns + 'switch_controller')
        self.assertIsNotNone(switch, 'the spawner never switched controllers on')
        loaded = [r['name'] for r in self.calls.of(ns + 'load_controller')]
        self.assertEqual(loaded, ['joint_state_controller', 'joint_head_controller'])
        self.assertEqual(switch['request']['start_controllers'], loaded)
        self.assertEqual(switch['request']['stop_controllers'], [])
        self.assertEqual(switch['request']['strictness'], 2)

    def test_spawner_unloads_its_controllers_when_stopped(self):
        rospy.set_param('/arm/arm_controller/type', 'position_controllers/JointPositionController')
        ns = '/arm/controller_manager/'
        proc = subprocess.Popen([self.spawner, '--namespace', '/arm', 'arm_controller',
                                 '__name:=arm_spawner'], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, universal_newlines=True)
        started = self.calls.wait_for(lambda c: c['service'] == ns + 'switch_controller')
        self.assertIsNotNone(started, 'the spawner did not start arm_controller')
        proc.send_signal(signal.SIGINT)         # as roslaunch stops it
        out, _ = proc.communicate(timeout=20)
        self.assertEqual(proc.returncode, 0, out)
        stop = self.calls.wait_for(lambda c: c['service'] == ns + 'switch_controller'
                                   and c['request']['stop_controllers'] == ['arm_controller'])
        self.assertIsNotNone(stop, out)
        self.assertEqual(self.calls.of(ns + 'unload_controller'), [{'name': 'arm_controller'}])
        self.assertIn('Shutting down spawner. Stopping and unloading controllers...', out)

    def test_spawner_says_which_parameter_a_controller_lacks(self):
        status, out = run([self.spawner, '--namespace=/robot', 'no_such_controller',
                           '__name:=lost_spawner'])
        self.assertEqual(status, 1, out)
        self.assertIn('Failed to load no_such_controller: the parameter '
                      '/robot/no_such_controller/type is not set', out)

    def test_spawner_refuses_an_unknown_option(self):
        status, out = run([self.spawner, '--fast', 'a'])
        self.assertEqual(status, 2)
        self.assertIn("spawner: unknown option '--fast'", out)

    def test_spawn_model_failures_exit_non_zero_with_the_reason(self):
        rospy.set_param('/taken_description', rospy.get_param('/robot/robot_description'))
        status, out = run([self.spawn_model, '-urdf', '-param', 'taken_description', '-model',
                           'taken', '__name:=taken_spawner'])
        self.assertEqual(status, 1, out)
        self.assertIn('Spawn status: SpawnModel: Failure - entity taken already exists.', out)
        self.assertIn('Spawn service failed. Exiting.', out)
        began = time.monotonic()
        status, out = run([self.spawn_model, '-urdf', '-param', 'taken_description', '-model',
                           'm', '-gazebo_namespace', '/nowhere', '-timeout', '1',
                           '__name:=lost_spawner'])
        self.assertEqual(status, 1, out)
        self.assertLess(time.monotonic() - began, 15)
        self.assertIn('/nowhere/spawn_urdf_model did not appear within 1 s', out)
        status, out = run([self.spawn_model, '-urdf', '-param', 'no_such_param', '-model', 'm',
                           '__name:=empty_spawner'])
        self.assertEqual(status, 1, out)
        self.assertIn('Error: param no_such_param is empty or does not exist', out)
        status, out = run([self.spawn_model, '-urdf', '-param', 'p', '-model', 'm', '-x',
                           'north'])
        self.assertEqual(status, 2)
        self.assertIn("spawn_model: -x must be a finite number, not 'north'", out)

    def test_gzclient_without_a_display_says_so_and_stays(self):
        # the one the launch file started is up ...
        self.assertTrue(rosnode.rosnode_ping('/gazebo_gui', max_count=1))
        # ... and one more says why there is no window, stays, and stops when told
        env = dict(os.environ, DISPLAY='', WAYLAND_DISPLAY='')
        proc = subprocess.Popen([self.gzclient, '__name:=gazebo_gui_2'], env=env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                universal_newlines=True)
        line = proc.stdout.readline()
        self.assertIn('gzclient: no display (DISPLAY is not set), so no viewer window; the '
                      'simulation runs on. Set DISPLAY (or run under xvfb-run) to see it in '
                      'rviz', line)
        self.assertIsNone(proc.poll())
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=20)
        self.assertEqual(proc.returncode, 0, out)

    def test_gzserver_refuses_what_it_cannot_run(self):
        # an option Gazebo does not know is ignored, as its parser does; a world that
        # is not there is refused (another node name: a simulator started as /gazebo
        # would replace the recording stand-in the other tests talk to)
        status, out = run([self.gzserver, '--fast', '/no/such.world', '__name:=gazebo3'])
        self.assertEqual(status, 2, out)
        self.assertNotIn("unknown option '--fast'\n", out)   # not what it refused
        self.assertIn("gzserver: world file '/no/such.world' not found", out)
        status, out = run([self.gzserver, '-e', 'ode', '/no/such.world', '__name:=gazebo2'])
        self.assertEqual(status, 2)
        self.assertIn("gzserver: world file '/no/such.world' not found", out)

    def test_empty_world_launch_takes_gazebos_arguments(self):
        status, out = run(['roslaunch', '--args', 'gazebo', 'gazebo_ros', 'empty_world.launch',
                           'paused:=true', 'verbose:=true', 'recording:=true', 'gui:=false',
                           'physics:=bullet', 'extra_gazebo_args:=--seed 3', 'output:=log',
                           'respawn_gazebo:=false', 'server_required:=true', 'headless:=true',
                           'use_clock_frequency:=true', 'pub_clock_frequency:=50',
                           'enable_ros_network:=false', 'gui_required:=true',
                           'world_name:=worlds/empty.world'])
        self.assertEqual(status, 0, out)
        command = out.strip().split()
        self.assertTrue(command[0].endswith('gazebo_ros/scripts/gzserver'), out)
        self.assertEqual(command[1:10], ['-u', '-r', '--verbose', '-e', 'bullet', '--seed', '3',
                                         'worlds/empty.world', '__name:=gazebo'])
        status, out = run(['roslaunch', '--nodes', 'gazebo_ros', 'empty_world.launch'])
        self.assertEqual((status, out.split()), (0, ['/gazebo', '/gazebo_gui']))


if __name__ == '__main__':
    rostest.rosrun('exp_assignment2', 'launch_surface', LaunchSurfaceTest)

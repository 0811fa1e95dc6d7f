"""The simulator node (``scripts/simulator.py``, node name ``gazebo``): what
Gazebo and gazebo_ros were for the originals.

It loads the world from its ``~`` parameters (``config/world_*.yaml``),
steps pybullet at a fixed step, paces it against the wall clock, publishes
``/clock`` and runs each model's plugins (drives, odometry, joint states,
camera). Gazebo's services: ``~pause_physics``, ``~unpause_physics``,
``~reset_world`` (std_srvs/Empty), so ``/gazebo/...`` with the node's name.
Subscriber callbacks only queue work; pybullet runs in this thread alone.
"""
import collections
import os
import threading
import time

import rospkg
import rospy
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty, EmptyResponse

from exp_assignment2.ros.clock_watch import watch_clock
from exp_assignment2.sim.limits import check_node_params
from exp_assignment2.sim.pacing import Pacer
from exp_assignment2.sim.physics import Physics
from exp_assignment2.sim.plugins import load_plugins
from exp_assignment2.sim.world import parse_world

# The node's own parameters; every other ~ parameter is the world's.
NODE_PARAMS = {'real_time_factor': 1.0, 'time_step': 0.01, 'renderer': 'gl', 'paused': False,
               'cmd_timeout': None, 'camera_width': None, 'camera_height': None,
               'camera_rate': None, 'camera_hfov': None, 'wait_for_camera': False,
               'start_timeout': 30.0, 'hidden': [], 'urdf_dir': None}


class Simulator(object):
    """Owns the physics, the plugins and the stepping loop."""

    def __init__(self, params):
        self.params = check_node_params(     # one line naming a refused parameter
            dict(NODE_PARAMS, **{k: v for k, v in params.items() if k in NODE_PARAMS}))
        self.world = parse_world({k: v for k, v in params.items() if k not in NODE_PARAMS})
        self._apply_overrides()
        self.renderer_kind = str(self.params['renderer'])
        self.physics = Physics(self.world, self._urdf_text, float(self.params['time_step']),
                               egl=self.renderer_kind == 'egl')
        self.pacer = Pacer(float(self.params['real_time_factor']))
        self.pending = collections.deque()      # work queued by callbacks
        self.stop = threading.Event()
        self.paused = bool(self.params['paused'])
        self.drives, self.frame_worker = {}, None
        self.camera_overrides = {key: self.params['camera_' + key]
                                 for key in ('width', 'height', 'rate', 'hfov')
                                 if self.params['camera_' + key] is not None}
        for name in self.params['hidden'] or []:
            self._start_hidden(name)
        self.clock_pub = rospy.Publisher('/clock', Clock, queue_size=10)
        watch_clock(lambda: self.physics.time)      # an ERROR naming a second /clock publisher
        self.plugins = []
        for model in self.world.models:
            self.plugins.extend(load_plugins(self, model))
        self.cameras = [pl for pl in self.plugins if hasattr(pl, 'wanted')]
        self._before = [pl.before_step for pl in self.plugins if hasattr(pl, 'before_step')]
        self._after = [pl.after_step for pl in self.plugins if hasattr(pl, 'after_step')]
        rospy.Service('~pause_physics', Empty, self._on_pause)
        rospy.Service('~unpause_physics', Empty, self._on_unpause)
        rospy.Service('~reset_world', Empty, self._on_reset)
        rospy.loginfo('simulator: %d models, step %.4f s, real_time_factor %g%s',
                      len(self.world.models), self.physics.time_step, self.pacer.rtf,
                      ', paused' if self.paused else '')

    def _apply_overrides(self):
        timeout = self.params['cmd_timeout']
        if timeout is not None:     # one value for every drive (0: keep the last command)
            for model in self.world.models:
                for drive in ('diff_drive', 'planar_move'):
                    if drive in model.plugins:
                        model.plugins[drive]['cmd_timeout'] = float(timeout)

    def _urdf_text(self, spec):
        if spec.description:
            text = rospy.get_param(spec.description, None)
            if not isinstance(text, str) or not text.strip():
                raise ValueError('model %s: no URDF in parameter %s' % (spec.name,
                                                                         spec.description))
            return text
        urdf_dir = self.params['urdf_dir'] or os.path.join(
            rospkg.RosPack().get_path('exp_assignment2'), 'urdf')
        path = spec.urdf if os.path.isabs(spec.urdf) else os.path.join(urdf_dir, spec.urdf)
        if not os.path.exists(path):
            raise ValueError('model %s: no URDF at %s' % (spec.name, path))
        with open(path) as f:
            return f.read()

    def _start_hidden(self, name):
        body = self.physics.bodies.get(name)
        if body is None or body.kinematic is None:
            raise ValueError('~hidden: %r is not a kinematic model of the world' % name)
        body.hidden = body.spawn_hidden = True
        self.physics.place_kinematic(name)

    # callbacks: queue, never touch pybullet
    def run_in_loop(self, fn):
        self.pending.append(fn)

    def _call_in_loop(self, fn, timeout=5.0):
        done = threading.Event()

        def call():
            fn()
            done.set()
        self.pending.append(call)
        return done.wait(timeout)

    def _on_pause(self, _req):
        self.paused = True
        return EmptyResponse()

    def _on_unpause(self, _req):
        self.paused = False
        return EmptyResponse()

    def _on_reset(self, _req):
        self._call_in_loop(self.reset)
        return EmptyResponse()

    def reset(self):
        """Gazebo's reset_world: every body back at its spawn pose, at rest;
        the clock keeps running."""
        for name in self.physics.bodies:
            self.physics.reset_body(name)
        for plugin in self.plugins:
            if hasattr(plugin, 'reset'):
                plugin.reset()

    # the loop
    def publish_clock(self):
        stamp = rospy.Time(0, self.physics.steps * int(round(self.physics.time_step * 1e9)))
        self.clock_pub.publish(Clock(clock=stamp))
        return stamp

    def wait_for_camera(self, timeout):
        """Hold the world still until a camera has a subscriber (or ``timeout``
        wall s): at real_time_factor 0 it would otherwise run ahead of nodes
        that are still starting."""
        end = time.monotonic() + timeout
        while not any(c.wanted() for c in self.cameras):
            if time.monotonic() > end or self.stop.is_set():
                rospy.logwarn('simulator: no camera subscriber after %.0f s; starting anyway',
                              timeout)
                return
            self.publish_clock()
            self.stop.wait(0.05)

    def spin(self):
        self.publish_clock()
        if self.params['wait_for_camera'] and self.cameras:
            self.wait_for_camera(float(self.params['start_timeout']))
        self.pacer.restart(self.physics.time)
        while not self.stop.is_set():
            while self.pending:
                self.pending.popleft()()
            if self.paused:         # the clock stands still but is still published
                self.publish_clock()
                self.stop.wait(0.05)
                self.pacer.restart(self.physics.time)
                continue
            self.step()
            delay = self.pacer.delay(self.physics.time)
            if delay > 0:
                self.stop.wait(delay)

    def step(self):
        for apply in self._before:
            apply()
        self.physics.step()
        self._guard()
        stamp = self.publish_clock()
        for publish in self._after:
            publish(stamp)

    def _guard(self):
        """A body whose state went non-finite is put back where it spawned."""
        for name in self.drives:
            if name in self.physics.bodies and not self.physics.finite(name):
                rospy.logerr('simulator: %s had a non-finite pose; put back at its spawn pose',
                             name)
                self.physics.reset_body(name)
                self.drives[name].reset()

    def close(self):
        if self.frame_worker is not None:
            self.frame_worker.close()
        self.physics.close()


def main():
    rospy.init_node('gazebo')
    try:
        sim = Simulator(rospy.get_param('~'))
    except (ValueError, KeyError, RuntimeError) as exc:
        rospy.logfatal('simulator: %s', exc)
        raise SystemExit(1)
    rospy.on_shutdown(sim.stop.set)
    try:
        sim.spin()
    finally:
        sim.close()

"""The simulator's engine, a small Gazebo with no ROS in it.

:class:`Engine` holds the world: it spawns models from URDF text (each with
the plugins its ``<gazebo>`` tags name, see :mod:`.plugins.base`), deletes
them, steps physics at a fixed step, paces simulated time against the wall
clock (``real_time_factor``; 0: as fast as possible), pauses, and resets the
world (bodies back where they were spawned) or the whole simulation (time
back to 0 too). Work from other threads is queued with :meth:`Engine.call_soon`
and runs in the simulation thread, the only one that touches pybullet.

Which plugin serves which ``<plugin filename>`` is the host's choice (a
registry, e.g. the ROS plugins of :mod:`exp_assignment2.sim.plugins`); the
unit tests and the benchmark drive the engine with no ROS master at all.
"""
import collections
import logging
import math
import threading

from exp_assignment2.sim import plugin_loading, releases, scripted_ball, urdf as urdf_reader
from exp_assignment2.sim.calls import Calls
from exp_assignment2.sim.model import Model
from exp_assignment2.sim.pacing import MAX_REAL_TIME_FACTOR, Pacer
from exp_assignment2.sim.physics import Physics
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.sim.poses import MAX_COORDINATE, world_region
from exp_assignment2.sim.plugins.base import EngineHandle, Plugin

INFINITE_BOUNDS = (-math.inf, math.inf, -math.inf, math.inf)
# The guard's world: a body farther than this beyond the bounds, or below
# -FALL_DEPTH in a world with bounds (the package's, which have a floor), has
# left it. A world without bounds (an SDF world) lets bodies fall, as Gazebo.
GUARD_MARGIN = 10.0
FALL_DEPTH = 10.0


class SpawnError(ValueError):
    """A model that cannot be spawned: the world is left unchanged."""


class _Log(object):
    """The default logger (Python's logging), one line per call."""

    def __init__(self):
        self._log = logging.getLogger('exp_assignment2.sim')

    def info(self, text):
        self._log.info(text)

    def warn(self, text):
        self._log.warning(text)

    def error(self, text):
        self._log.error(text)


class Engine(object):
    """The world and its clock (see the module docstring).

    :param registry: ``{filename: Plugin subclass}``; other plugin file names
        are ignored: one warning for a library the release's Gazebo had,
        Gazebo's error for one it did not (:mod:`.gazebo_libraries`)
    :param bounds: (x_min, x_max, y_min, y_max) that driven bodies keep within
    :param settings: host settings handed to plugins (``EngineHandle.settings``);
        ``ros_release`` names the :class:`~.releases.Release` its plugins follow,
        ``ball_script`` a course for the ball (:mod:`.scripted_ball`)
    :param log: an object with ``info``, ``warn``, ``error`` (default: logging)
    :param max_real_time_factor: real_time_factor 0's ceiling (0: none; see
        :mod:`.pacing`)
    """

    def __init__(self, time_step=0.01, real_time_factor=1.0, registry=None, bounds=None,
                 egl=False, settings=None, log=None, paused=False,
                 max_real_time_factor=MAX_REAL_TIME_FACTOR):
        self.settings = dict(settings or {})
        self.release = releases.release(self.settings.get('ros_release'))  # ReleaseError
        self.bounds = tuple(bounds) if bounds is not None else INFINITE_BOUNDS
        self.scripted_ball = scripted_ball.start(self, self.settings.get('ball_script'))
        self.physics = Physics(time_step, egl=egl)
        self.time_step = self.physics.time_step
        self._step_ns = int(round(self.time_step * 1e9))
        self.pacer = Pacer(real_time_factor, max_real_time_factor=max_real_time_factor)
        self.registry = dict(registry or {})
        self._guard_logs = {}          # model name -> RefusalLog
        self._guard_region = world_region(
            self.bounds, GUARD_MARGIN,
            -FALL_DEPTH if all(map(math.isfinite, self.bounds)) else -MAX_COORDINATE)
        self.log = log or _Log()
        self.models = collections.OrderedDict()
        self.plugins = collections.OrderedDict()     # model name -> [Plugin]
        self.steps, self.generation, self.paused = 0, 0, bool(paused)
        self.handle = EngineHandle(self)
        self._calls = Calls()
        self._shared = {}
        self._warned = set()
        self._hooks = ([], [])          # (before, after) bound methods, rebuilt on change
        self.step_listeners = []        # fn(engine) after every step (the host's clock)
        self.frame_listeners = []       # fn(camera, t, bgr) for every frame a camera draws
        self.stop = threading.Event()

    # time
    @property
    def time(self):
        """Simulated time (s): steps x step, so it never drifts."""
        return self.steps * self.time_step

    @property
    def time_ns(self):
        return self.steps * self._step_ns

    # models
    def spawn(self, name, urdf_text, pose=(0.0, 0.0, 0.0, 0.0, 0.0, 0.0), namespace='',
              base_dir='.', grid=False, hidden=False):
        """Add a model; returns its :class:`Model`. SpawnError (the world
        unchanged) for a taken name, a pose that is not finite or a URDF that
        cannot be read; a plugin that cannot load is logged and left out, as
        Gazebo leaves it out (:mod:`.plugin_loading`)."""
        if not name or not isinstance(name, str):
            raise SpawnError('a model needs a name')
        if name in self.models:
            raise SpawnError('a model named %r exists already' % name)
        pose = tuple(pose)
        if len(pose) == 4:                    # (x, y, z, yaw)
            pose = pose[:3] + (0.0, 0.0, pose[3])
        if len(pose) != 6 or not all(isinstance(v, (int, float)) and math.isfinite(v)
                                     for v in pose):
            raise SpawnError('model %s: the pose %s is not 6 finite numbers' % (name, pose))
        try:
            urdf = urdf_reader.parse(urdf_text, base_dir, spawn_rpy=pose[3:])
        except ValueError as exc:
            raise SpawnError('model %s: %s' % (name, exc))
        try:
            model = Model(self.physics, name, urdf, pose, namespace, grid, hidden)
        except ValueError as exc:
            raise SpawnError('model %s: %s' % (name, exc))
        for text in urdf.errors:
            self.log.error('model %s: %s' % (name, text))
        for text in urdf.warnings + urdf.gazebo.warnings:
            self.log.warn('model %s: %s' % (name, text))
        plugins = None
        try:
            plugins = plugin_loading.load(model, self.registry, self.handle, self._warned)
        finally:
            if plugins is None:      # broken: the world unchanged
                model.remove()
        self.models[name] = model
        self.plugins[name] = plugins
        if self.scripted_ball is not None:
            self.scripted_ball.spawned(model)
        self._changed()
        return model

    def delete(self, name):
        """Remove a model and close its plugins; SpawnError if there is none."""
        if name not in self.models:
            raise SpawnError('there is no model named %r' % name)
        for plugin in self.plugins.pop(name):
            plugin.close()
        self.models.pop(name).remove()
        if self.scripted_ball is not None:
            self.scripted_ball.deleted(name)
        self._changed()

    def _changed(self):
        self.generation += 1
        every = [pl for pls in self.plugins.values() for pl in pls]
        self._hooks = ([pl.before_step for pl in every
                        if type(pl).before_step is not Plugin.before_step],
                       [pl.after_step for pl in every
                        if type(pl).after_step is not Plugin.after_step])

    def shared(self, key, factory):
        if key not in self._shared:
            self._shared[key] = factory()
        return self._shared[key]

    # work from other threads (:mod:`.calls`)
    def call_soon(self, fn):
        """Queue ``fn()`` for the simulation thread (thread-safe)."""
        self._calls.soon(fn)

    def call_and_wait(self, fn, timeout=5.0):
        """Run ``fn()`` in the simulation thread and return its result (or raise
        what it raised); TimeoutError if the loop does not get to it."""
        return self._calls.and_wait(fn, timeout)

    # stepping
    def step(self):
        """One step: commands, the ball script, physics, the guard, publishers."""
        before, after = self._hooks
        for hook in before:
            hook()
        if self.scripted_ball is not None:
            self.scripted_ball.before_physics()
        self.physics.step()
        self.steps += 1
        self._guard()
        for hook in after:
            hook()
        for listener in self.step_listeners:
            listener(self)

    def _guard(self):
        """A dynamic body whose state went non-finite, or that left the world
        (see GUARD_MARGIN), is put back where it spawned."""
        for model in self.models.values():
            trouble = (None if model.static or model.kinematic
                       else model.trouble(self._guard_region))
            if trouble:        # one line per model and 5 s (a floorless world's bounds)
                if model.name not in self._guard_logs:
                    self._guard_logs[model.name] = RefusalLog(
                        'simulator: ' + model.name, self.log.error, period=5.0,
                        what='times put back')
                self._guard_logs[model.name]('%s; put back at its spawn pose' % trouble)
                model.reset()
                for plugin in self.plugins[model.name]:
                    plugin.reset()

    def run(self, idle=None):
        """Step until :attr:`stop` is set, paced against the wall clock; while
        paused, ``idle()`` is called every 50 ms of wall time (the host keeps
        publishing its clock)."""
        self.pacer.restart(self.time)
        while not self.stop.is_set():
            self._calls.run()
            if self.paused:
                if idle is not None:
                    idle()
                self.stop.wait(0.05)
                self.pacer.restart(self.time)
                continue
            self.step()
            delay = self.pacer.delay(self.time)
            if delay > 0:
                self.stop.wait(delay)

    def run_for(self, seconds):
        """Step ``seconds`` of simulated time at once (tests, the benchmark)."""
        for _ in range(int(round(seconds / self.time_step))):
            self._calls.run()
            self.step()

    # resets
    def reset_world(self):
        """Gazebo's reset_world: every model back at its spawn pose, at rest,
        plugins reset; the clock keeps running."""
        for name, model in self.models.items():
            model.reset()
            for plugin in self.plugins[name]:
                plugin.reset()
        if self.scripted_ball is not None:
            self.scripted_ball.place(self.time)

    def reset_simulation(self):
        """Gazebo's reset_simulation: reset_world, and simulated time back to 0."""
        self.steps = 0
        self.pacer.restart(self.time)
        self.reset_world()

    def close(self):
        self.stop.set()
        for name in list(self.plugins):
            for plugin in self.plugins.pop(name):
                plugin.close()
        for shared in self._shared.values():
            if hasattr(shared, 'close'):
                shared.close()
        self.physics.close()


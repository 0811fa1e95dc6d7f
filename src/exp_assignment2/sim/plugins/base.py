"""The plugin contract: what a model's plugin is given and may do (no ROS).

A model brings its plugins in its URDF's ``<gazebo>`` tags, as in Gazebo.
When a model is spawned, the engine makes one :class:`Plugin` per
``<plugin filename="...">`` it knows (the registry maps file names to
classes) and gives it three things:

* ``self.model``: the :class:`~exp_assignment2.sim.model.Model` it belongs to
  (poses, twist, joints; joint motors, base velocity, pose);
* ``self.options``: its ``<plugin>`` element's children, read through
  :class:`Options` (typed, with defaults, as gazebo_ros' ``getParameter``),
  and ``self.sensor``, the ``<sensor>`` it sits in, if any;
* ``self.engine``: an :class:`EngineHandle`, the narrow view of the engine:
  simulated time, the time step, the world's bounds, :meth:`~EngineHandle.call_soon`
  to run work in the simulation thread, shared resources, the host's settings
  and the ROS release whose plugins it follows (:mod:`exp_assignment2.sim.releases`).

And the engine calls its hooks, always from the simulation thread:

* :meth:`Plugin.load` once, after the model is in the world (raise
  :class:`PluginError` when it cannot run: it is logged and left out, the
  model stays, as Gazebo leaves out a plugin whose Load throws);
* :meth:`Plugin.before_step` before every physics step (apply commands);
* :meth:`Plugin.after_step` after every step (read state, publish);
* :meth:`Plugin.reset` on reset_world and reset_simulation (time may go back);
* :meth:`Plugin.close` when the model is deleted or the engine closes.

And it answers two questions of a grader's (the ground truth,
:mod:`exp_assignment2.sim.model_facts`): :meth:`Plugin.facts`, what it is
(its file, the sensor it sits in, the topic it takes commands on), and
:attr:`Plugin.commands_taken`, how many commands it has taken so far.

A plugin touches nothing else: callbacks from other threads (ROS
subscribers) hand work to the simulation thread with ``call_soon``.
"""
import re


NUMBER = re.compile(r'\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?')


def stream_number(text):
    """What ``std::stringstream >> double`` reads of ``text``: its leading
    number (``0.3m``: 0.3), or None when it does not start with one (``inf``
    and ``nan`` included, as a C++ stream)."""
    match = NUMBER.match(text)
    return float(match.group(0)) if match else None


class PluginError(ValueError):
    """A plugin that cannot load, with the reason (a bad option, no such joint):
    it does not run, the model does (:mod:`~exp_assignment2.sim.plugin_loading`).
    ``gazebo_line``: what Gazebo itself logs for it, when not the usual
    "Exception occured in the Load function..."."""

    def __init__(self, text, gazebo_line=None):
        ValueError.__init__(self, text)
        self.gazebo_line = gazebo_line


class Options(object):
    """A plugin's options: the ``<plugin>`` element's children as text.

    Reads are typed as gazebo_ros reads them; a value a plugin cannot run
    with raises :class:`PluginError` naming it; options a plugin never reads
    are ignored, as Gazebo ignores them. ``notes``: what was read otherwise
    than written (for the log). ``overrides`` (the host's settings for this
    kind of plugin) win over what the URDF says.
    """

    def __init__(self, values, where, overrides=None):
        self.values, self.where = dict(values), where
        self.values.update(overrides or {})
        self.notes = []

    def has(self, name):
        return name in self.values and self.values[name] not in ('', None)

    def raw(self, name, default=None):
        """The value as given: text, or a dict for an element with children."""
        return self.values.get(name, default)

    def text(self, name, default=''):
        value = self.values.get(name)
        if value is None or isinstance(value, dict):
            return default
        return str(value).strip() or default

    def number(self, name, default, minimum=None, positive=False, nonzero=False):
        """A number as sdformat hands it to gazebo_ros' getParameter: read
        like a C++ stream (``0.3m`` is 0.3; ``fast`` is 0, with a note), then
        checked: PluginError when the plugin cannot run with it (Gazebo would
        divide by it, or its physics would go non-finite)."""
        value = self.values.get(name)
        if value is None or value == '' or isinstance(value, dict):
            return default
        result = stream_number(str(value))
        if result is None:
            result = 0.0
            self.notes.append('%s: <%s> %r is not a number: Gazebo reads it as 0'
                              % (self.where, name, value))
        if (positive and result <= 0) or (minimum is not None and result < minimum) or (
                nonzero and result == 0):
            need = ('positive' if positive else 'at least %g' % minimum if minimum is not None
                    else 'other than 0')
            raise PluginError('%s: <%s> must be %s, got %r' % (self.where, name, need, value))
        return result

    def boolean(self, name, default):
        value = self.values.get(name)
        if value is None or value == '':
            return default
        text = str(value).strip().lower()
        if text in ('1', 'true'):
            return True
        if text in ('0', 'false'):
            return False
        raise PluginError('%s: <%s> must be true or false, got %r' % (self.where, name, value))


class EngineHandle(object):
    """The engine as a plugin sees it (see the module docstring)."""

    def __init__(self, engine):
        self._engine = engine

    @property
    def time(self):
        """Simulated time (s)."""
        return self._engine.time

    @property
    def time_ns(self):
        """Simulated time (integer ns: exact, for stamps)."""
        return self._engine.time_ns

    @property
    def time_step(self):
        return self._engine.time_step

    def frame_drawn(self, camera, when, bgr):
        """A camera's frame is done (``when``: its simulated time, s): the
        engine's frame listeners see it (a grader's ground truth)."""
        for listener in self._engine.frame_listeners:
            listener(camera, when, bgr)

    @property
    def bounds(self):
        """(x_min, x_max, y_min, y_max): no driven body leaves this square."""
        return self._engine.bounds

    @property
    def settings(self):
        """The host's settings (dict), e.g. camera size overrides, command timeout."""
        return self._engine.settings

    @property
    def release(self):
        """The ROS release whose Gazebo plugins this world follows
        (:class:`~exp_assignment2.sim.releases.Release`)."""
        return self._engine.release

    @property
    def log(self):
        """The host's logger: ``info``, ``warn``, ``error`` (one line each)."""
        return self._engine.log

    def call_soon(self, fn):
        """Run ``fn()`` in the simulation thread before the next step (thread-safe)."""
        self._engine.call_soon(fn)

    def call_and_wait(self, fn, timeout=5.0):
        """Run ``fn()`` in the simulation thread and return its result (a
        service answering from another thread); TimeoutError if the loop does
        not get to it in ``timeout`` wall s."""
        return self._engine.call_and_wait(fn, timeout)

    def shared(self, key, factory):
        """One object per engine for ``key`` (made by ``factory()`` the first
        time), e.g. the camera's frame worker shared by every camera."""
        return self._engine.shared(key, factory)

    def make_renderer(self, kind):
        """A camera renderer backend (gl, egl, tiny) drawing this engine's world
        (see :mod:`exp_assignment2.sim.camera`)."""
        from exp_assignment2.sim.camera import make_renderer
        physics = self._engine.physics
        return make_renderer(kind, self, physics.client, physics.egl_plugin is not None)

    def scene(self):
        """The world for drawing: (generation, models); the generation changes
        whenever a model is spawned or deleted."""
        return self._engine.generation, list(self._engine.models.values())


class Plugin(object):
    """A model plugin (see the module docstring). Subclasses name the
    ``<plugin filename>`` values they serve in ``FILENAMES``."""

    FILENAMES = ()

    def __init__(self, model, decl, engine, overrides=None):
        self.model, self.decl, self.engine = model, decl, engine
        self.name, self.filename, self.sensor = decl.name, decl.filename, decl.sensor
        self.options = Options(decl.options, 'model %s: plugin %s (%s)'
                               % (model.name, decl.name or '?', decl.filename), overrides)
        # gazebo_ros' spawn gives its robot namespace only to a plugin without
        # one of its own (gazebo_ros_api_plugin's walkChildAddRobotNamespace)
        self.namespace = (self.options.text('robotNamespace').strip('/')
                          if self.options.has('robotNamespace')
                          else model.namespace or self.default_namespace())

    def default_namespace(self):
        """The robot namespace with none given (gazebo_ros' plugins: the root)."""
        return ''

    def topic(self, name):
        """``name`` under the plugin's robot namespace (absolute names stay)."""
        if name.startswith('/'):
            return name
        return '/%s/%s' % (self.namespace, name) if self.namespace else '/' + name

    def load(self):
        """Set up (publishers, subscribers, controllers); PluginError when it cannot run."""

    def before_step(self):
        """Apply commands before a physics step."""

    def after_step(self):
        """Read the world after a step; publish what is due."""

    def reset(self):
        """reset_world / reset_simulation: forget commands; time may have gone back."""

    def close(self):
        """The model is deleted or the engine closes: release everything."""

    def facts(self):
        """What the plugin is, as plain data: its file and name, the sensor it
        sits in (type, name, link); subclasses add what they take commands on."""
        out = {'file': self.filename, 'name': self.name}
        if self.sensor is not None:
            out['sensor'] = {'type': self.sensor.type, 'name': self.sensor.name,
                             'link': self.sensor.link}
        return out

    @property
    def commands_taken(self):
        """Commands taken from outside so far (a drive's velocity commands)."""
        return 0

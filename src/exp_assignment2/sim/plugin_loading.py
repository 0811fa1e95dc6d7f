"""A model's plugins loaded as Gazebo's ``Model::LoadPlugin`` loads them (no ROS).

Gazebo loads each ``<plugin>`` of a model on its own: a library it cannot find
logs ``Failed to load plugin ...``; a plugin whose ``Load`` throws (a joint it
needs is missing) logs ``Exception occured in the Load function of plugin ...
This plugin will not run.``; a plugin that logs its own error and returns
(gazebo_ros_control without its services) stays inert. In every case the
model is in the world with its other plugins. So here: a plugin that raises
:class:`~.plugins.base.PluginError` (or ValueError) in ``load`` gets one error
line, its reason and Gazebo's words, and is left out; nothing is refused.
"""
from exp_assignment2.sim import gazebo_libraries
from exp_assignment2.sim.plugins.base import PluginError


def load(model, registry, engine, warned):
    """The loaded plugins of ``model``: ``registry`` maps file names to
    classes, ``engine`` is the :class:`~.plugins.base.EngineHandle` they get,
    ``warned`` the file names already said to be not simulated (one line each)."""
    plugins = []
    try:
        for decl in model.urdf.gazebo.plugins:
            cls = registry.get(decl.filename)
            if cls is None:
                _not_simulated(model, decl, engine, warned)
                continue
            plugin = cls(model, decl, engine)
            try:
                plugin.load()
            except (PluginError, ValueError, KeyError) as exc:
                _notes(plugin, engine)
                reason = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
                if not reason.startswith('model %s:' % model.name):
                    reason = 'model %s: %s' % (model.name, reason)
                engine.log.error('%s; %s' % (reason, getattr(exc, 'gazebo_line', None) or
                                             gazebo_libraries.not_run(decl.name, decl.filename)))
                close_quietly(plugin)
                continue
            _notes(plugin, engine)
            plugins.append(plugin)
    except BaseException:
        for plugin in plugins:
            close_quietly(plugin)
        raise
    return plugins


def _notes(plugin, engine):
    for note in plugin.options.notes:
        engine.log.warn(note)


def _not_simulated(model, decl, engine, warned):
    """A library the release's Gazebo had: one warning per file name; one it
    did not have: Gazebo's error, every time (Gazebo says it every time)."""
    if not gazebo_libraries.installed(decl.filename, engine.release.name):
        engine.log.error('model %s: %s' % (model.name, gazebo_libraries.missing(decl.filename)))
    elif decl.filename not in warned:
        warned.add(decl.filename)
        engine.log.warn('model %s: plugin %s (%s) is not simulated here; ignored'
                        % (model.name, decl.name, decl.filename))


def close_quietly(plugin):
    """Close a plugin whose load failed half way (what it holds may be half made)."""
    try:
        plugin.close()
    except Exception:       # noqa: BLE001 - its own failure was logged already
        pass

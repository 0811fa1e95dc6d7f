"""A URDF's ``<gazebo>`` extension tags, read as Gazebo reads them (no ROS).

Gazebo users describe in their URDF what Gazebo adds to a model:

* ``<gazebo><plugin name filename>...</plugin></gazebo>``: a model plugin
  (``libgazebo_ros_diff_drive.so``...) with its options as child elements;
* ``<gazebo reference="link"><sensor type="camera">...<plugin/></sensor>``:
  a sensor on a link, and the plugin that publishes it;
* ``<gazebo reference="link"><material>Gazebo/Red</material>``: the link's
  colour in Gazebo (:data:`GAZEBO_MATERIALS`), ``<gravity>0</gravity>`` or
  ``<turnGravityOff>true</turnGravityOff>``, ``<mu1>``/``<mu2>`` friction;
* ``<gazebo><static>true</static></gazebo>``: a model that never moves;
  ``<gazebo><allow_auto_disable>false</allow_auto_disable></gazebo>``: a model
  the physics never puts to rest (SDF's default: true).

:func:`read` returns them as plain data (:class:`GazeboTags`); which plugin
serves which file name is the engine's business, not this module's.
"""
from collections import OrderedDict, namedtuple

from exp_assignment2.sim.gazebo_materials import GAZEBO_MATERIALS, UNKNOWN

SensorDecl = namedtuple('SensorDecl', 'type name link update_rate always_on pose options')
SensorDecl.__doc__ = """A ``<sensor>`` on ``link``: ``pose`` (x, y, z, roll, pitch, yaw)
in the link frame, ``options`` its other elements as nested dicts of text
(e.g. ``options['camera']['image']['width']``)."""


class PluginDecl(namedtuple('PluginDecl', 'name filename options reference sensor')):
    """A ``<plugin>``: its options are its child elements as text (nested
    elements as dicts); ``reference`` is the link of a ``<gazebo reference>``
    (None for a model plugin) and ``sensor`` the :class:`SensorDecl` it sits in."""


class GazeboTags(object):
    """Everything a URDF's ``<gazebo>`` tags say (see the module docstring).

    ``plugins``: :class:`PluginDecl` in file order; ``colours``: link ->
    RGBA; ``gravity_off``: links with gravity off; ``friction``: link ->
    (mu1, mu2); ``static``: the model never moves; ``auto_disable``: the
    physics may put it to rest (SDF's ``allow_auto_disable``); ``sensors``:
    every :class:`SensorDecl`, with a plugin or not; ``warnings``: what was
    not understood (a colour name, a bad number), for the caller to log."""

    def __init__(self):
        self.plugins, self.colours, self.friction, self.sensors = [], {}, {}, []
        self.gravity_off, self.static, self.warnings = set(), False, []
        self.auto_disable = True
        self._references = []

    def references(self):
        """Every ``reference`` named, in order."""
        return list(self._references)


def element_dict(elem):
    """An element's children as an ordered dict: text for leaves, dicts for
    elements with children (the last of repeated tags wins, as Gazebo's
    ``GetElement``)."""
    out = OrderedDict()
    for child in elem:
        if not isinstance(child.tag, str):
            continue      # a comment
        out[child.tag] = element_dict(child) if len(child) else (child.text or '').strip()
    return out


def _truth(text):
    return str(text).strip().lower() in ('1', 'true')


def _number(text, what, tags):
    try:
        return float(text)
    except (TypeError, ValueError):
        tags.warnings.append('%s: %r is not a number; ignored' % (what, text))
        return None


def _sensor(elem, link, tags):
    rate = _number(elem.findtext('update_rate', '0'), 'sensor %s update_rate'
                   % elem.get('name'), tags)
    pose = [0.0] * 6
    if elem.findtext('pose'):
        try:
            pose = [float(v) for v in elem.findtext('pose').split()]
            assert len(pose) == 6
        except (ValueError, AssertionError):
            tags.warnings.append('sensor %s: pose %r is not 6 numbers; ignored'
                                 % (elem.get('name'), elem.findtext('pose')))
            pose = [0.0] * 6
    options = element_dict(elem)
    for key in ('plugin', 'update_rate', 'pose', 'always_on'):
        options.pop(key, None)
    return SensorDecl(elem.get('type', ''), elem.get('name', ''), link, rate or 0.0,
                      _truth(elem.findtext('always_on', 'true')), tuple(pose), options)


def _plugin(elem, reference, sensor):
    return PluginDecl(elem.get('name', ''), elem.get('filename', ''), element_dict(elem),
                      reference, sensor)


def read(robot):
    """The :class:`GazeboTags` of a parsed ``<robot>`` element."""
    tags = GazeboTags()
    for gz in robot.findall('gazebo'):
        ref = gz.get('reference')
        if ref:
            tags._references.append(ref)
        for child in gz:
            if not isinstance(child.tag, str):
                continue
            tag = child.tag
            if tag == 'plugin':
                tags.plugins.append(_plugin(child, ref, None))
            elif tag == 'sensor':
                sensor = _sensor(child, ref, tags)
                tags.sensors.append(sensor)
                plugins = child.findall('plugin')
                if not plugins:
                    tags.warnings.append('sensor %s on %s has no plugin: nothing publishes it'
                                         % (sensor.name, ref))
                tags.plugins.extend(_plugin(p, ref, sensor) for p in plugins)
            elif tag == 'material' and ref:
                name = (child.text or '').strip()
                if name not in GAZEBO_MATERIALS:
                    tags.warnings.append('link %s: Gazebo material %r is not known here; drawn '
                                         'grey' % (ref, name))
                tags.colours[ref] = GAZEBO_MATERIALS.get(name, UNKNOWN)
            elif tag in ('gravity', 'turnGravityOff') and ref:
                off = _truth(child.text) if tag == 'turnGravityOff' else not _truth(child.text)
                if off:
                    tags.gravity_off.add(ref)
            elif tag in ('mu1', 'mu2') and ref:
                value = _number(child.text, 'link %s %s' % (ref, tag), tags)
                if value is not None:
                    mu = list(tags.friction.get(ref, (None, None)))
                    mu[tag == 'mu2'] = value
                    tags.friction[ref] = tuple(mu)
            elif tag == 'static' and not ref:
                tags.static = _truth(child.text)
            elif tag == 'allow_auto_disable' and not ref:
                tags.auto_disable = _truth(child.text)
    return tags

"""Where the parts of an SDF document come from (plain Python: no ROS).

:class:`Sources` is what reading one world or model needs besides the
document: the table of known model sizes (``config/gazebo_model_sizes.yaml``,
:func:`load_model_sizes`), where Gazebo models are installed
(``GAZEBO_MODEL_PATH``, ``~/.gazebo/models``), what an ``<include>`` brings in
(an installed model, Gazebo's ``ground_plane`` or ``sun``, or a box of the
known size) and which stand-ins were used, for the notes.
"""
import math
import os
import xml.etree.ElementTree as ET
from collections import OrderedDict

import numpy as np
import yaml

from exp_assignment2.layout import PACKAGE
from exp_assignment2.sim.sdf_geometry import DEFAULT_RGBA, SdfError, pose_of
from exp_assignment2.sim.sdf_model import Link, Model, flag, read_model

SIZES_FILE = os.path.join(PACKAGE, 'config', 'gazebo_model_sizes.yaml')
SIZES_NAME = 'config/gazebo_model_sizes.yaml'
MAX_INCLUDE_DEPTH = 8
# A mesh of a model the table does not know, in a link that declares no size (no
# box, cylinder or sphere collision to size it by): a visual box of this size,
# scaled by the mesh's <scale>, standing on the mesh's origin, and no collision
# (docs/original_env_supplies.md)
DEFAULT_MESH_BOX = {'size': [1.0, 1.0, 1.0], 'center': [0.0, 0.0, 0.5], 'rgba': DEFAULT_RGBA,
                    'static': True, 'mass': 1.0, 'default': True}
GROUND_PLANE = """<model name="ground_plane"><static>true</static><link name="link">
<collision name="collision"><geometry><plane><normal>0 0 1</normal><size>100 100</size></plane>
</geometry></collision><visual name="visual"><geometry><plane><normal>0 0 1</normal>
<size>100 100</size></plane></geometry><material><script><name>Gazebo/Grey</name></script>
</material></visual></link></model>"""


def load_model_sizes(path=SIZES_FILE):
    """The known model sizes: name -> {size, center, rgba, static, mass}."""
    try:
        with open(path) as f:
            table = yaml.safe_load(f) or {}
    except (IOError, yaml.YAMLError) as exc:
        raise SdfError('%s: cannot read the model sizes: %s' % (path, exc))
    sizes = {}
    for name, entry in table.items():
        try:
            size = [float(v) for v in entry['size']]
            center = [float(v) for v in entry.get('center', [0, 0, size[2] / 2])]
            if len(size) != 3 or len(center) != 3 or min(size) <= 0 or not all(
                    math.isfinite(v) for v in size + center):
                raise ValueError('size and center are 3 finite numbers, sizes positive')
            rgba = [float(v) for v in entry.get('rgba', DEFAULT_RGBA)]
            if len(rgba) != 4 or not all(0 <= v <= 1 for v in rgba):
                raise ValueError('rgba is 4 numbers in [0, 1]')
            sizes[str(name)] = {'size': size, 'center': center, 'rgba': tuple(rgba),
                                'static': bool(entry.get('static', True)),
                                'mass': float(entry.get('mass', 1.0))}
        except (KeyError, TypeError, ValueError, AttributeError) as exc:
            raise SdfError('%s: entry %r: %s' % (path, name, exc))
    return sizes


class Sources(object):
    """What reading one document needs: the size table, where models are
    installed, the stand-ins used so far, the model being read."""

    def __init__(self, sizes, model_path, base_dir):
        self.sizes = load_model_sizes() if sizes is None else sizes
        if model_path is None:
            model_path = [p for p in os.environ.get('GAZEBO_MODEL_PATH', '').split(os.pathsep)
                          if p] + [os.path.expanduser('~/.gazebo/models')]
        self.model_path, self.base_dir = list(model_path), base_dir
        self.used = OrderedDict()        # uri -> [entry, installed, model names]
        self.model, self.depth = '', 0
        self.skipped = []                # lines: what Gazebo builds and this does not

    def find_model_dir(self, name):
        for root in self.model_path:
            path = os.path.join(root, name)
            if os.path.isdir(path):
                return path
        return None

    def mesh_file(self, uri):
        """The installed file a mesh URI names, or None."""
        if uri.startswith('model://'):
            name, _, rest = uri[len('model://'):].partition('/')
            root = self.find_model_dir(name)
            path = os.path.join(root, rest) if root else None
        else:
            path = uri[len('file://'):] if uri.startswith('file://') else uri
            path = os.path.join(self.base_dir, path) if not os.path.isabs(path) else path
        return path if path and os.path.isfile(path) else None

    def knows(self, uri):
        """Whether the size table knows the model of a mesh URI."""
        return _model_name(uri) in self.sizes

    def stand_in(self, uri, where, installed, declared=None):
        """The entry that stands in for a mesh, recorded for the notes: the size
        table's for a model it knows, else a box of the ``declared`` size (m,
        what the visual's link declares), else :data:`DEFAULT_MESH_BOX`."""
        entry = self.sizes.get(_model_name(uri))
        if entry is None and declared is not None:
            entry = {'size': list(declared), 'rgba': DEFAULT_RGBA, 'declared': True}
        entry = entry or DEFAULT_MESH_BOX
        key = (uri, tuple(entry['size']))
        self.used.setdefault(key, [entry, installed, []])
        if self.model not in self.used[key][2]:
            self.used[key][2].append(self.model)
        return entry

    def include(self, elem, where):
        """The model an ``<include>`` brings in: None for a light (the sun), and
        for what sdformat skips with an error (no ``<uri>``, a model it cannot
        find), which is said in the notes, as the world loads without it."""
        uri = elem.findtext('uri', '').strip()
        where = '%s/include[%s]' % (where, uri)
        if not uri:
            self.left_out("%s: <include> element missing 'uri' attribute (sdformat skips it)"
                          % where)
            return None
        if self.depth >= MAX_INCLUDE_DEPTH:
            raise SdfError('%s: includes nested deeper than %d (a loop?)'
                           % (where, MAX_INCLUDE_DEPTH))
        name = uri[len('model://'):].strip('/') if uri.startswith('model://') else None
        directory = self.find_model_dir(name) if name else self._directory(uri)
        self.depth += 1
        try:
            if directory:
                model = self._installed(directory, where)
            elif name == 'sun':
                return None
            elif name == 'ground_plane':
                model = read_model(ET.fromstring(GROUND_PLANE), where + '/model[ground_plane]',
                                   self)
            elif name in self.sizes:
                model = self._box_model(name, uri)
            else:       # sdformat: "Unable to find uri[...]", and the world loads without it
                self.left_out('%s: Unable to find uri[%s]: model %r is not installed '
                              '(GAZEBO_MODEL_PATH) and has no known size in %s; left out, as '
                              'sdformat leaves it out' % (where, uri, name or uri, SIZES_NAME))
                return None
        finally:
            self.depth -= 1
        model.name = elem.findtext('name', '').strip() or model.name
        if elem.find('pose') is not None:
            model.pose = pose_of(elem, where)
        if elem.find('static') is not None:
            model.static = flag(elem, 'static')
        return model

    def _directory(self, uri):
        path = uri[len('file://'):] if uri.startswith('file://') else uri
        path = os.path.join(self.base_dir, path) if not os.path.isabs(path) else path
        return path if os.path.isdir(path) else None

    def _installed(self, directory, where):
        sdf_file = 'model.sdf'
        config = os.path.join(directory, 'model.config')
        if os.path.isfile(config):
            try:
                sdf_file = (ET.parse(config).getroot().findtext('sdf') or sdf_file).strip()
            except ET.ParseError as exc:
                raise SdfError('%s: %s is not valid XML: %s' % (where, config, exc))
        root = parse_xml(os.path.join(directory, sdf_file), where)
        model = root.find('model') if root.tag == 'sdf' else None
        if model is None:
            raise SdfError('%s: %s has no <model>' % (where, sdf_file))
        outer, self.base_dir = self.base_dir, directory
        try:
            return read_model(model, '%s/model[%s]' % (where, model.get('name', '')), self)
        finally:
            self.base_dir = outer

    def _box_model(self, name, uri):
        entry = self.stand_in(uri, '', installed=False)
        model = Model(name, np.eye(4), entry['static'])
        link = Link('link', np.eye(4))
        box = np.eye(4)
        box[:3, 3] = entry['center']
        sx, sy, sz = entry['size']
        m = entry['mass']
        link.inertial = (m, box, (m * (sy * sy + sz * sz) / 12, 0.0, 0.0,
                                  m * (sx * sx + sz * sz) / 12, 0.0, m * (sx * sx + sy * sy) / 12))
        shape = ('box', {'size': list(entry['size'])})
        link.visuals.append(('visual', box, shape, entry['rgba']))
        link.collisions.append(('collision', box, shape, None))
        model.links['link'] = link
        return model

    def left_out(self, line):
        """Something Gazebo builds that is left out here, said in the notes."""
        self.skipped.append(line)

    def notes(self):
        """One line per stand-in: which mesh, which box, in which models; then
        one per thing left out."""
        lines = []
        for (uri, _), (entry, installed, models) in self.used.items():
            named = ', '.join(models[:3]) + (', ...' if len(models) > 3 else '')
            lines.append('%s %s: a %s m box stands in (%s), in %d model%s: %s' % (
                uri, 'is COLLADA, which the simulator does not load' if installed
                else 'is not installed',
                ' x '.join('%.2f' % v for v in entry['size']),
                'the default for a model not in %s; seen, not collided with' % SIZES_NAME
                if entry.get('default') else
                "the size its link's box, cylinder and sphere collisions declare; seen, its "
                "link's collisions collide" if entry.get('declared') else SIZES_NAME,
                len(models), '' if len(models) == 1 else 's', named))
        return lines + self.skipped


def _model_name(uri):
    """The model a mesh URI belongs to (``model://NAME/...``), else its file's name."""
    return (uri[len('model://'):].split('/')[0] if uri.startswith('model://')
            else os.path.splitext(os.path.basename(uri))[0])


def parse_xml(source, where):
    """The root element of a file path or XML text."""
    try:
        if source.lstrip().startswith('<'):
            return ET.fromstring(source)
        return ET.parse(source).getroot()
    except ET.ParseError as exc:
        raise SdfError('%s: not valid XML: %s' % (where, exc))
    except (IOError, OSError) as exc:
        raise SdfError('%s: cannot read %s: %s' % (where, source, exc))

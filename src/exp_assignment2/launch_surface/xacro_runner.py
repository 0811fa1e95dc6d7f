"""``$(find xacro)/xacro``: xacro, the ROS 1 one, for a Gazebo launch file.

Debian has no xacro; ``tools/run original-env`` installs PyPI's ``xacro``
1.13 (ROS 1's, whose ``$(find pkg)`` is roslaunch's, so it finds the user's
own package in the overlay) for ``/usr/bin/python3``. ``--inorder`` (``-i``)
is accepted and dropped: in-order processing is xacro's default since
Melodic, and passing it on only makes xacro print a deprecation warning into
every launch.

``load_yaml`` is Noetic's (xacro 1.14): 1.13's calls ``yaml.load`` without a
loader, which Debian's PyYAML 6 refuses, so every robot that read its sizes
from a YAML file failed. Noetic's loads safely, gives dotted access to the
YAML's keys (``${dims.chassis.mass}`` as well as ``${dims['chassis']['mass']}``)
and reads ``!radians`` and ``!degrees`` expressions.
"""
import math
import sys

XACRO_VERSION = '1.13.3'
IN_ORDER = ('--inorder', '-i')


def xacro_argv(argv):
    """The arguments to hand to xacro: ``--inorder`` and ``-i`` dropped."""
    return [a for a in argv if a not in IN_ORDER]


def main(argv=None):
    """Run xacro on the given arguments, as ``rosrun xacro xacro`` would."""
    argv = sys.argv[1:] if argv is None else argv
    try:
        import xacro
    except ImportError:
        print('xacro: the xacro module is not installed for %s; bash tools/run original-env '
              'installs it (xacro==%s from PyPI)' % (sys.executable, XACRO_VERSION),
              file=sys.stderr)
        return 1
    sys.argv = [sys.argv[0]] + xacro_argv(argv)
    use_noetic_load_yaml(xacro)
    return xacro.main()


def use_noetic_load_yaml(xacro):
    """Give the ``xacro`` module (1.13) Noetic's ``load_yaml``."""
    import yaml

    def no_such_key(key):
        return xacro.XacroException("No such key: '%s'" % (key,))

    def wrap(item):
        if isinstance(item, dict):
            return YamlDict(item)
        return YamlList(item) if isinstance(item, list) else item

    class YamlDict(dict):
        def __getattr__(self, key):
            try:
                return wrap(dict.__getitem__(self, key))
            except KeyError:
                if key.startswith('__'):        # copy's and pickle's probes
                    raise AttributeError(key)
                raise no_such_key(key)
        __getitem__ = __getattr__

    class YamlList(list):
        def __getitem__(self, index):
            return wrap(list.__getitem__(self, index))

        def __iter__(self):
            return (wrap(item) for item in list.__iter__(self))

    def radians(loader, node):
        value = loader.construct_scalar(node)
        try:
            if '__' in value:          # as xacro's safe_eval: no way out of the math names
                raise ValueError('"__" is not allowed')
            return float(eval(value, {'__builtins__': {}}, vars(math)))
        except Exception as exc:
            raise xacro.XacroException('invalid expression: %s (%s)' % (value, exc))

    class Loader(yaml.SafeLoader):
        pass
    Loader.add_constructor('!radians', radians)
    Loader.add_constructor('!degrees', lambda loader, node: math.radians(radians(loader, node)))

    def load_yaml(filename):
        filename = xacro.abs_filename_spec(filename)
        old = xacro.push_file(filename)
        try:
            with open(filename) as f:
                return wrap(yaml.load(f, Loader=Loader))
        finally:
            xacro.restore_filestack(old)
            xacro.all_includes.append(filename)

    xacro.load_yaml = load_yaml
    xacro.global_symbols['load_yaml'] = load_yaml

"""One Python package ``exp_assignment2`` for the user's package and this one.

When the user's package is also called exp_assignment2, two catkin devel
spaces each have a Python package of that name, and the overlay's (the
user's: only its generated messages) would hide this repository's (its
library, ``exp_assignment2.nodes``, ``exp_assignment2.minismach``, ..., and
its messages). The overlay puts a package of its own first on PYTHONPATH:

* ``exp_assignment2.__path__``: the user's directories first (the devel
  space's, then the sources of a ``catkin_python_setup``), then this
  repository's; so a module both have is the user's;
* ``exp_assignment2.msg`` (and ``.srv``, when both have one): the user's
  types, completed with this repository's types the user's package lacks
  (this repository's nodes need ``Gesture`` and ``PlanningAction``). A type
  both define is the user's: the same ``Planning.action`` gives the same
  message, so this repository's servers and the user's clients agree.

Nothing is written in the user's directory or in either devel space.
"""
import os
import re

_EXTENDED = re.compile(r"^__extended_path = '([^']*)'\.split\(';'\)", re.MULTILINE)

INIT = '''"""exp_assignment2 of original-env --package: the user's package, then this repository's.

Written by src/exp_assignment2/original_env/overlay/python_package.py; see there.
"""
__path__ = {path!r}
for __init_file in {inits!r}:
    with open(__init_file) as __f:
        exec(compile(__f.read(), __init_file, 'exec'))
for __name in ('__init_file', '__f', '__name'):
    globals().pop(__name, None)
'''

KIND_INIT = '''"""exp_assignment2.{kind}: the user's types, then this repository's that the user lacks.

Written by src/exp_assignment2/original_env/overlay/python_package.py; see there.
"""
# A submodule (_Planning.py, ...) is looked up in this order: the user's first.
__path__ = {path!r}
for __init_file in [__d + '/__init__.py' for __d in reversed(__path__)]:
    with open(__init_file) as __f:
        exec(compile(__f.read(), __init_file, 'exec'))
for __name in ('__init_file', '__f', '__d', '__name'):
    globals().pop(__name, None)
'''


def package_dirs(devel_package):
    """A devel space's package directory and the source directories it extends to.

    catkin writes ``__extended_path = '<src>;...'`` into the devel space's
    ``__init__.py`` of a package with ``catkin_python_setup()``; genpy leaves
    an empty one for a package that only has messages; an install space's
    package is one directory, the library and its messages together.
    """
    dirs = [devel_package]
    init = os.path.join(devel_package, '__init__.py')
    if os.path.exists(init):
        with open(init) as f:
            match = _EXTENDED.search(f.read())
        if match:
            name = os.path.basename(devel_package)
            dirs += [os.path.join(p, name) for p in match.group(1).split(';')
                     if os.path.isdir(os.path.join(p, name))]
    return dirs


def write_merged(target, user_devel_package, own_devel_package):
    """Write the merged package into ``target`` (``<dir>/exp_assignment2``);
    ``own_devel_package``: this package's, in the devel space or installed."""
    user_dirs, own_dirs = package_dirs(user_devel_package), package_dirs(own_devel_package)
    # the packages' own __init__.py: the sources catkin's relay points at, or
    # the package itself where there is no relay (an install space's)
    sources = [os.path.join(d, '__init__.py') for d in own_dirs[1:] or own_dirs[:1]]
    sources += [os.path.join(d, '__init__.py') for d in user_dirs[1:]]
    sources = [path for path in sources if os.path.exists(path)]
    os.makedirs(target, exist_ok=True)
    _write(os.path.join(target, '__init__.py'),
           INIT.format(path=[target] + user_dirs + own_dirs, inits=sources))
    for kind in ('msg', 'srv'):
        kind_dirs = [os.path.join(d, kind) for d in (user_devel_package, own_devel_package)]
        merged = os.path.join(target, kind)
        if all(os.path.exists(os.path.join(d, '__init__.py')) for d in kind_dirs):
            os.makedirs(merged, exist_ok=True)
            _write(os.path.join(merged, '__init__.py'), KIND_INIT.format(kind=kind, path=kind_dirs))
        elif os.path.exists(os.path.join(merged, '__init__.py')):
            os.unlink(os.path.join(merged, '__init__.py'))
            os.rmdir(merged)


def _write(path, text):
    with open(path, 'w') as f:
        f.write(text)

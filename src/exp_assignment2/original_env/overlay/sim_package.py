"""This repository's package under a second name, exp_assignment2_sim.

With ``original-env --package DIR`` the name exp_assignment2 is the user's
package (``rospack find``, ``rosrun``, ``$(find ...)``), so this
repository's simulator, servers and launch files are reached as
``exp_assignment2_sim``: ``roslaunch exp_assignment2_sim simulator.launch``,
``rosrun exp_assignment2_sim go_to_point_ball.py``.

The package is a directory on ROS_PACKAGE_PATH, nothing to build: a
package.xml, a link to every top-level entry of this package's folder (the
repository; from an install space, share/exp_assignment2, with ``scripts``
linking to lib/exp_assignment2, where catkin installs the executables), and
the launch files rewritten so that what they find, start and include is
exp_assignment2_sim's (``$(find exp_assignment2)``, ``pkg="exp_assignment2"``,
``find('exp_assignment2')`` in ``$(eval ...)``). Nodes learn the name from
``EXP2_SIM_PACKAGE`` (the simulator reads its URDF files through it).
"""
import os
import re
import shutil

NAME = 'exp_assignment2_sim'
ORIGINAL = 'exp_assignment2'
_NOT_LINKED = frozenset(('.git', 'launch', 'package.xml', 'CMakeLists.txt'))
_LAUNCH_SUFFIXES = ('.launch', '.xml', '.test')

_REFERENCES = (
    re.compile(r'(\$\(find\s+)%s(\s*\))' % ORIGINAL),
    re.compile(r'''(\bpkg\s*=\s*["'])%s(["'])''' % ORIGINAL),
    re.compile(r'''(\bfind\(\s*["'])%s(["']\s*\))''' % ORIGINAL),
)

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.0.0</version>
  <description>
    This repository's exp_assignment2 (simulator, servers, launch files) under
    a second name, for original-env --package, where exp_assignment2 is the
    user's package. Written by src/exp_assignment2/original_env/overlay/sim_package.py.
  </description>
  <maintainer email="exp_assignment2@example.com">exp_assignment2 developers</maintainer>
  <license>BSD</license>
</package>
'''


def rewrite_launch(text, name=NAME):
    """A launch file's references to exp_assignment2 made references to ``name``."""
    for pattern in _REFERENCES:
        text = pattern.sub(lambda m: m.group(1) + name + m.group(2), text)
    return text


def write_package(package_dir, target, scripts=None):
    """(Re)write the second-name package of ``package_dir`` (the folder
    holding its package.xml) in ``target``; ``scripts``: the folder of its
    executables when they are not in it (an install space's), linked as scripts/."""
    if os.path.isdir(target):
        shutil.rmtree(target)
    os.makedirs(target)
    with open(os.path.join(target, 'package.xml'), 'w') as f:
        f.write(PACKAGE_XML.format(name=NAME))
    for entry in sorted(os.listdir(package_dir)):
        if entry not in _NOT_LINKED:
            os.symlink(os.path.join(package_dir, entry), os.path.join(target, entry))
    if scripts:
        os.symlink(scripts, os.path.join(target, 'scripts'))
    launch = os.path.join(package_dir, 'launch')
    for root, _dirs, files in os.walk(launch):
        out_dir = os.path.join(target, 'launch', os.path.relpath(root, launch))
        os.makedirs(out_dir, exist_ok=True)
        for name in files:
            source, out = os.path.join(root, name), os.path.join(out_dir, name)
            if name.endswith(_LAUNCH_SUFFIXES):
                with open(source) as f:
                    text = rewrite_launch(f.read())
                with open(out, 'w') as f:
                    f.write(text)
            else:
                os.symlink(source, out)

"""original-env's overlay when this package runs from a catkin install space
(exp_assignment2.layout): the second package name and the merged Python
package from the installed folders. No ROS, no build."""
import os
import subprocess
import sys

from exp_assignment2.original_env.overlay import python_package, sim_package


def write(path, text='', mode=None):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(text)
    if mode:
        os.chmod(path, mode)


def test_the_second_package_of_an_install_space_links_its_executables(tmp_path):
    """Installed, the package's folder is share/exp_assignment2 and its
    executables are in lib/exp_assignment2: linked as scripts/, where rosrun
    and roslaunch look for exp_assignment2_sim's."""
    share, lib = tmp_path / 'share' / 'exp_assignment2', tmp_path / 'lib' / 'exp_assignment2'
    write(str(share / 'package.xml'), '<package/>')
    write(str(share / 'launch' / 'sim.launch'), '<node pkg="exp_assignment2" type="a.py"/>')
    write(str(share / 'config' / 'dog.yaml'))
    write(str(lib / 'a.py'), '', 0o755)
    target = str(tmp_path / 'packages' / sim_package.NAME)
    sim_package.write_package(str(share), target, scripts=str(lib))
    assert sorted(os.listdir(target)) == ['config', 'launch', 'package.xml', 'scripts']
    assert os.path.realpath(os.path.join(target, 'scripts', 'a.py')) == str(lib / 'a.py')
    with open(os.path.join(target, 'launch', 'sim.launch')) as f:
        assert 'pkg="exp_assignment2_sim"' in f.read()


def test_the_merged_package_takes_an_installed_library_whole(tmp_path):
    """An install space's exp_assignment2 is one folder (the library, its
    messages, its own __init__.py), with no catkin relay: merged after the
    user's, its __init__.py run too."""
    user = tmp_path / 'user' / 'devel' / 'exp_assignment2'
    write(str(user / '__init__.py'))
    write(str(user / 'msg' / '__init__.py'), 'from ._Ball import *\n')
    write(str(user / 'msg' / '_Ball.py'), 'Ball = "user"\n')
    ours = tmp_path / 'install' / 'lib' / 'python3' / 'dist-packages' / 'exp_assignment2'
    write(str(ours / '__init__.py'), 'LIBRARY = "installed"\n')
    write(str(ours / 'vision.py'), 'WHO = "ours"\n')
    write(str(ours / 'msg' / '__init__.py'), 'from ._Gesture import *\n')
    write(str(ours / 'msg' / '_Gesture.py'), 'Gesture = "ours"\n')
    merged = tmp_path / 'merged' / 'exp_assignment2'
    python_package.write_merged(str(merged), str(user), str(ours))
    code = ('import exp_assignment2, exp_assignment2.vision as v\n'
            'from exp_assignment2.msg import Ball, Gesture\n'
            'print(Ball, Gesture, v.WHO, exp_assignment2.LIBRARY)\n')
    out = subprocess.run([sys.executable, '-c', code], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, universal_newlines=True, cwd=str(tmp_path),
                         env=dict(os.environ, PYTHONPATH=str(tmp_path / 'merged')))
    assert out.stdout.split() == ['user', 'ours', 'ours', 'installed'], out.stdout

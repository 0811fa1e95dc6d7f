"""exp_assignment2.layout tells the source tree from a catkin install space
by where it is itself: the same file in both places (no ROS, no build)."""
import os
import shutil
import subprocess
import sys

from exp_assignment2 import layout

SHOW = ('import json, exp_assignment2.layout as l; print(json.dumps([l.INSTALLED, l.REPO, '
        'l.ROOT, l.PACKAGE, l.SCRIPTS, l.LIBRARY, l.STAND_INS, l.underlay_setup("/ws"), '
        'l.own_python_package("/ws")]))')


def where(library):
    """What layout.py decides when it is imported from ``library``."""
    import json
    out = subprocess.run([sys.executable, '-I', '-c', 'import sys; sys.path.insert(0, %r); %s'
                          % (str(library), SHOW)], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, universal_newlines=True, check=True)
    return json.loads(out.stdout)


def place(library):
    """layout.py (and an empty package around it) in ``library``."""
    package = library / 'exp_assignment2'
    package.mkdir(parents=True)
    (package / '__init__.py').write_text('')
    shutil.copy(layout.__file__, str(package / 'layout.py'))


def test_the_source_tree(tmp_path):
    repo = tmp_path / 'repo'
    place(repo / 'src')
    (repo / 'package.xml').write_text('<package/>')
    assert where(repo / 'src') == [
        False, str(repo), str(repo), str(repo), str(repo / 'scripts'), str(repo / 'src'),
        str(repo / 'tools' / 'stand_ins'), '/ws/devel/setup.bash',
        '/ws/devel/lib/python3/dist-packages/exp_assignment2']


def test_an_install_space(tmp_path):
    prefix = tmp_path / 'install'
    library = prefix / 'lib' / 'python3' / 'dist-packages'
    place(library)
    (prefix / 'share' / 'exp_assignment2').mkdir(parents=True)
    (prefix / 'share' / 'exp_assignment2' / 'package.xml').write_text('<package/>')
    share = str(prefix / 'share')
    assert where(library) == [
        True, None, str(prefix), os.path.join(share, 'exp_assignment2'),
        str(prefix / 'lib' / 'exp_assignment2'), str(library), share,
        str(prefix / 'setup.bash'), str(library / 'exp_assignment2')]


def test_this_checkout_is_a_source_tree():
    assert not layout.INSTALLED
    assert os.path.isfile(os.path.join(layout.PACKAGE, 'package.xml'))
    assert os.path.isfile(os.path.join(layout.SCRIPTS, 'simulator.py'))
    assert os.path.isdir(os.path.join(layout.STAND_INS, 'gazebo_msgs'))

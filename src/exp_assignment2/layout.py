"""Where this package's files are, decided here once: in its source tree (what
the devel space runs: catkin's devel package points at ``src/``) or in a
catkin install space (``catkin_make install``: the files copied under a
prefix), told apart by where this file is.

===============  ==========================  ====================================
                 source tree (devel space)   install space (PREFIX)
===============  ==========================  ====================================
``LIBRARY``      REPO/src                    PREFIX/lib/python3/dist-packages
``PACKAGE``      REPO                        PREFIX/share/exp_assignment2
``SCRIPTS``      REPO/scripts                PREFIX/lib/exp_assignment2
``ROOT``         REPO                        PREFIX
``STAND_INS``    REPO/tools/stand_ins        PREFIX/share
===============  ==========================  ====================================

``LIBRARY`` holds the Python package (and, in an install space, the data
folders setup.py's ``package_data`` installs with it: original_env's
startup/, programs/, shims/, stand_in_packages/); ``PACKAGE`` the ROS
package (package.xml, launch/, config/, urdf/, rviz/); ``SCRIPTS`` the
executables; ``ROOT`` everything of this package (what a grading run's
sandbox shows read-only); ``STAND_INS`` the folder on ROS_PACKAGE_PATH that
holds the message stand-ins tools/stand_ins builds beside this package
(gazebo_msgs, controller_manager_msgs, ...). ``REPO`` is None in an install
space: tools/, test/ and bench/ are not installed.

Standard library only and no import of the package, so that a script run
on its own (the grader's driver in its sandbox) can import it.
"""
import os

NAME = 'exp_assignment2'
LIBRARY = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))


def _install_prefix(library):
    """The prefix an installed library sits in (PREFIX/lib/python3/dist-packages):
    the nearest folder above it with share/exp_assignment2/package.xml, else
    catkin's three levels up."""
    folder = library
    for _ in range(4):
        folder = os.path.dirname(folder)
        if os.path.isfile(os.path.join(folder, 'share', NAME, 'package.xml')):
            return folder
    return os.path.dirname(os.path.dirname(os.path.dirname(library)))


_TOP = os.path.dirname(LIBRARY)
INSTALLED = not (os.path.basename(LIBRARY) == 'src'
                 and os.path.isfile(os.path.join(_TOP, 'package.xml')))
if INSTALLED:
    REPO = None
    ROOT = _install_prefix(LIBRARY)
    PACKAGE = os.path.join(ROOT, 'share', NAME)
    SCRIPTS = os.path.join(ROOT, 'lib', NAME)
    STAND_INS = os.path.join(ROOT, 'share')
else:
    REPO = ROOT = PACKAGE = _TOP
    SCRIPTS = os.path.join(REPO, 'scripts')
    STAND_INS = os.path.join(REPO, 'tools', 'stand_ins')


def underlay_setup(workspace):
    """The setup file of the catkin space this package runs from: the
    workspace's devel space (``WORKSPACE/devel/setup.bash``), or the install
    space this library is in (its ``setup.bash``; ``workspace`` is then only
    where the original-code environment keeps its own files)."""
    if INSTALLED:
        return os.path.join(ROOT, 'setup.bash')
    return os.path.join(workspace, 'devel', 'setup.bash')


def own_python_package(workspace):
    """This package's Python package as the catkin space has it: the devel
    space's (its generated messages, pointing at ``src/`` for the rest), or
    the installed one (everything in one folder)."""
    if INSTALLED:
        return os.path.join(LIBRARY, NAME)
    return os.path.join(workspace, 'devel', 'lib', 'python3', 'dist-packages', NAME)

"""``$(find xacro)/xacro``: xacro, the ROS 1 one, for a Gazebo launch file.

Debian has no xacro; ``tools/run original-env`` installs PyPI's ``xacro``
1.13 (ROS 1's, whose ``$(find pkg)`` is roslaunch's, so it finds the user's
own package in the overlay) for ``/usr/bin/python3``. ``--inorder`` (``-i``)
is accepted and dropped: in-order processing is xacro's default since
Melodic, and passing it on only makes xacro print a deprecation warning into
every launch.
"""
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
    return xacro.main()

"""Start-up hook of the original-code environment (tools/original_env/shell.sh).

Python imports ``sitecustomize`` at start-up from the first directory of
sys.path that has one; this directory is on PYTHONPATH only inside that
environment. It does seven things:

1. runs the ``sitecustomize`` it shadows (Debian's, or one further down
   PYTHONPATH), so nothing the system configured is lost;
2. unless both EXP2_TAB_RULE and EXP2_PY2 are 0, installs the import hook that
   reads a module as Python 2 did where Python 3 cannot: the tab rule for a
   file Python 3 refuses for tabs in its indentation, 2to3's translation for
   Python 2 code (exp2_tab_import.py, exp2_py2_read.py; the script itself is
   python_launcher.sh's business, or that of a catkin relay script's ``compile``);
3. when a display is configured (DISPLAY, WAYLAND_DISPLAY or an explicit
   QT_QPA_PLATFORM such as ``offscreen``) and EXP2_CV2_GUI_THREAD is not 0,
   arranges for cv2's HighGUI calls to run on one GUI thread once cv2 is
   imported (see exp2_cv2_gui.py for why). cv2 itself is not imported here;
4. unless EXP2_XMLRPC_END is 0, arranges for rospy's XML-RPC thread to end
   when the node shuts down, as it did under Python 2, instead of polling a
   closed socket at 100 % of a core (exp2_xmlrpc_end.py);
5. unless EXP2_NODE_START is 0, has roslaunch start a node's file as the
   students' machines did: one whose first line names Python 2
   (``#!/usr/bin/python``) on this shell's python, one without its execute
   bit as if it had it (exp2_node_start.py).
6. when EXP2_SEED is set (a run of the grader, with its seed), seeds Python's
   ``random`` with it, so that a run can be repeated as it was;
7. unless EXP2_KEYBOARD_WAIT is 0, when standard input is not a terminal,
   has the keyboard read as on a terminal nobody types into (or where
   EXP2_KEYBOARD's lines are typed): exp2_keyboard.py.

Without a display nothing is changed: cv2.imshow then behaves as OpenCV's Qt
backend does, which aborts the whole process ("could not connect to display",
exit status 134).
"""
import os
import sys


def _run_shadowed_sitecustomize():
    import importlib.machinery
    import importlib.util
    here = os.path.dirname(os.path.abspath(__file__))
    rest = [p for p in sys.path if os.path.abspath(p or os.curdir) != here]
    spec = importlib.machinery.PathFinder.find_spec('sitecustomize', rest)
    if spec is None or spec.loader is None or spec.origin == os.path.abspath(__file__):
        return
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except Exception as exc:  # as Python does for a failing sitecustomize
        sys.stderr.write('Error in sitecustomize %s: %r\n' % (spec.origin, exc))


def _display_configured():
    return any(os.environ.get(v) for v in ('DISPLAY', 'WAYLAND_DISPLAY', 'QT_QPA_PLATFORM'))


_run_shadowed_sitecustomize()
if os.environ.get('EXP2_TAB_RULE', '1') != '0' or os.environ.get('EXP2_PY2', '1') != '0':
    import exp2_tab_import
    exp2_tab_import.install()
    exp2_tab_import.install_for_catkin_relay(sys.modules['__main__'], getattr(sys, 'argv', []))
if os.environ.get('EXP2_CV2_GUI_THREAD', '1') != '0' and _display_configured():
    import exp2_cv2_import
    exp2_cv2_import.install()
if os.environ.get('EXP2_XMLRPC_END', '1') != '0':
    import exp2_xmlrpc_end
    exp2_xmlrpc_end.install()
if os.environ.get('EXP2_NODE_START', '1') != '0':
    import exp2_node_start
    exp2_node_start.install()
if os.environ.get('EXP2_SEED', '').isdigit():
    import random
    random.seed(int(os.environ['EXP2_SEED']))
if os.environ.get('EXP2_KEYBOARD_WAIT', '1') != '0':
    import exp2_keyboard
    exp2_keyboard.install()

"""Work out the environment of tools/original_env/shell.sh (PYTHONPATH, PATH).

Run it with the interpreter the original code will use (/usr/bin/python3) in
the environment it will inherit (workspace sourced). It prints shell
``export`` lines (``--json``: a JSON object) for:

* PYTHONPATH: gui/ first (sitecustomize.py: cv2 HighGUI on one thread), then
  what was there, then one shim directory per module that does not import
  *now*: smach, smach_ros. Each is checked in a fresh interpreter
  with the shims decided so far (smach_ros needs a smach), so a real module
  is never shadowed; the shims also come last.
* ROS_PACKAGE_PATH: $EXP2_LAUNCH_PACKAGES (shell.sh's executable copy of
  packages/: gazebo_ros, xacro, controller_manager, image_transport for the
  user's launch files; packages/README.md) first; EXP2_REPO: this repository.
* PATH: $EXP2_ORIGINAL_BIN (where shell.sh puts ``python`` and ``python3``,
  python_launcher.sh: /usr/bin/python3, with Python 2's tab rule for a script, also
  for ``#!/usr/bin/env python`` scripts such as the original's) and /usr/bin
  before the rest.
* EXP2_ORIGINAL_ENV: the one-line summary shell.sh prints.
"""
import json
import os
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON = '/usr/bin/python3'
# module to try -> shim directory that provides it
SHIMS = (
    ('smach', os.path.join(HERE, 'shims', 'smach')),
    ('smach_ros', os.path.join(HERE, 'shims', 'smach_ros')),
)


def _join(*parts):
    return os.pathsep.join(p for p in parts if p)


def imports(module, environ):
    """Does ``import module`` work in a fresh interpreter with this environment?"""
    env = dict(environ)
    env['EXP2_CV2_GUI_THREAD'] = '0'
    proc = subprocess.run([PYTHON, '-c', 'import ' + module], env=env, cwd='/',
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return proc.returncode == 0


def compute(environ):
    """Return the variables to set for the original-code environment."""
    base = environ.get('PYTHONPATH', '')
    shims, notes = [], []
    for module, directory in SHIMS:
        trial = dict(environ, PYTHONPATH=_join(base, *shims))
        name = module.split('.')[0]
        if imports(module, trial):
            notes.append('%s: installed one' % name)
        else:
            shims.append(directory)
            notes.append('%s: shim' % name)
    if environ.get('EXP2_TAB_RULE', '1') == '0':
        notes.append("tabs: Python 3's rule (EXP2_TAB_RULE=0)")
    else:
        notes.append("tabs: Python 2's rule where Python 3 refuses")
    if environ.get('EXP2_CV2_GUI_THREAD', '1') == '0':
        notes.append('cv2 GUI: unchanged (EXP2_CV2_GUI_THREAD=0)')
    elif any(environ.get(v) for v in ('DISPLAY', 'WAYLAND_DISPLAY', 'QT_QPA_PLATFORM')):
        notes.append('cv2 GUI: one HighGUI thread')
    else:
        notes.append('cv2 GUI: no DISPLAY, so cv2.imshow aborts the process as OpenCV does'
                     ' (use xvfb-run or QT_QPA_PLATFORM=offscreen)')
    # gazebo_ros, xacro, controller_manager, image_transport for the user's launch
    # files (packages/README.md)
    notes.append('gazebo_ros, xacro, controller_manager, image_transport: stand-ins')
    return {
        'ROS_PACKAGE_PATH': _join(environ.get('EXP2_LAUNCH_PACKAGES') or
                                  os.path.join(HERE, 'packages'),
                                  environ.get('ROS_PACKAGE_PATH', '')),
        'EXP2_REPO': os.path.dirname(os.path.dirname(HERE)),
        'PYTHONPATH': _join(os.path.join(HERE, 'gui'), base, *shims),
        'PATH': _join(environ.get('EXP2_ORIGINAL_BIN', ''), '/usr/bin', '/bin',
                      environ.get('PATH', '')),
        'EXP2_ORIGINAL_ENV': '; '.join(notes),
    }


def main(argv):
    result = compute(os.environ)
    if '--json' in argv:
        print(json.dumps(result))
    else:
        for key, value in result.items():
            print('export %s=%s' % (key, shlex.quote(value)))


if __name__ == '__main__':
    main(sys.argv[1:])

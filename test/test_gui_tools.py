"""rqt_image_view and smach_viewer in a user's launch file, in the original-code
shell (Debian has neither): they never end the launch; without a display each
says so in one line; on a display (Xvfb) the image window opens on the given
topic and smach_viewer finds the running machine through its introspection
server (the smach_ros shim's, in smach_msgs' stand-in).

The fixture package (test/fixtures/gui_tools_pkg) is put on ROS_PACKAGE_PATH;
both viewers are ``required``, so either ending would end the launch."""
import os
import shutil

import pytest

from test_gzclient_viewer import launch_with_viewer
from test_original_env_tabs import free_port

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIXTURE = os.path.join(REPO, 'test', 'fixtures', 'gui_tools_pkg')


def _script(tmp_path):
    root = tmp_path / 'packages'
    shutil.copytree(FIXTURE, str(root / 'gui_tools_pkg'))
    (root / 'gui_tools_pkg' / 'scripts' / 'patrol.py').chmod(0o755)
    port = free_port()
    return ('export ROS_PACKAGE_PATH=%s:$ROS_PACKAGE_PATH ROS_MASTER_URI=http://localhost:%d; '
            'exec roslaunch -p %d gui_tools_pkg gui_tools.launch 2>&1' % (root, port, port))


def _ended(text):
    return [line for line in text.splitlines()
            if 'process has died' in line or 'process has finished' in line
            or 'shutting down' in line.lower() and 'required' in line.lower()]


def test_without_a_display_each_says_so_once_and_the_launch_runs_on(tmp_path):
    text = launch_with_viewer(tmp_path, _script(tmp_path),
                              'smach_viewer: no display', xvfb=False)
    lines = text.splitlines()
    assert len([l for l in lines if 'rqt_image_view: no display (DISPLAY is not set), so no '
                'window for /patrol/image; the launch runs on' in l]) == 1, text[-3000:]
    assert len([l for l in lines if 'smach_viewer: no display (DISPLAY is not set), so no '
                'window; the launch runs on' in l]) == 1, text[-3000:]
    assert _ended(text) == [], text[-3000:]


def test_on_a_display_the_viewers_show_the_image_and_the_machine(tmp_path):
    text = launch_with_viewer(tmp_path, _script(tmp_path), 'smach_viewer: showing /SM_ROOT')
    assert 'rqt_image_view: showing /patrol/image on display' in text, text[-3000:]
    assert 'smach_viewer: showing /SM_ROOT: states ' in text
    shown = [l for l in text.splitlines() if 'smach_viewer: showing /SM_ROOT' in l]
    assert len(shown) == 1 and sorted(shown[0].split('states ')[1].split(', ')) == [
        'GARDEN', 'KITCHEN'], shown
    assert _ended(text) == [], text[-3000:]
    assert 'Traceback' not in text, text[-3000:]

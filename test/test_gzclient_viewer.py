"""gazebo_ros' gzclient in the original-code shell, on a display (Xvfb): a
Gazebo launch file (empty_world.launch with gui) starts with no rospack error
line (rviz, the viewer, depends on media_export, which Debian lacks), and a
robot spawned from its robot_description is drawn from it, on its link frames.

Needs the built workspace and xvfb-run; skipped without. It starts its own
master on a free port and ends the launch with SIGINT."""
import os
import shutil
import signal
import subprocess
import time

import pytest

from test_original_env_tabs import free_port, sourced_workspace

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHELL = os.path.join(REPO, 'tools', 'original_env', 'shell.sh')
SETTLE = 12.0       # wall s after rviz opened: it has asked rospack by then


def launch_with_viewer(tmp_path, script, ready, wall_seconds=180, xvfb=True):
    """Run ``script`` (bash) in the original-code shell, under xvfb-run (else
    with no display at all), until a line containing ``ready`` was printed and
    SETTLE s passed; its output."""
    workspace = sourced_workspace()
    if workspace is None:
        pytest.skip('no sourced catkin workspace (run it through tools/run test)')
    if xvfb and shutil.which('xvfb-run') is None:
        pytest.skip('needs xvfb-run (apt-get install xvfb)')
    env = dict(os.environ, ROS_HOME=str(tmp_path / 'ros_home'), PYTHONUNBUFFERED='1',
               EXP2_WS=workspace)
    env['PATH'] = '/usr/bin:' + env.get('PATH', '')
    for name in ('DISPLAY', 'WAYLAND_DISPLAY', 'QT_QPA_PLATFORM'):
        env.pop(name, None)
    out_path = tmp_path / 'out.txt'
    with open(str(out_path), 'w') as out:
        proc = subprocess.Popen((['xvfb-run', '-a'] if xvfb else []) +
                                ['bash', SHELL, 'bash', '-c', script],
                                env=env, stdout=out, stderr=subprocess.STDOUT,
                                start_new_session=True)
    try:
        deadline, seen = time.time() + wall_seconds, None
        while time.time() < deadline and proc.poll() is None:
            text = out_path.read_text(errors='replace')
            if seen is None and ready in text:
                seen = time.time()
            if seen is not None and time.time() - seen > SETTLE:
                break
            time.sleep(0.5)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGINT)
            try:
                proc.wait(30)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
    text = out_path.read_text(errors='replace')
    assert seen is not None, text[-3000:]
    return text


def test_a_gazebo_launch_with_its_viewer_prints_no_rospack_error(tmp_path):
    port = free_port()
    text = launch_with_viewer(tmp_path, 'export ROS_MASTER_URI=http://localhost:%d; exec '
                              'roslaunch -p %d gazebo_ros empty_world.launch 2>&1' % (port, port),
                              'gzclient: rviz on display')
    assert [line for line in text.splitlines() if 'rospack' in line] == [], text[-3000:]


def test_gzclient_draws_a_spawned_robot_from_its_description_on_its_moving_links(tmp_path):
    port = free_port()
    urdf = os.path.join(REPO, 'test', 'fixtures', 'spawned_robot.urdf')
    markers, tf = tmp_path / 'markers.txt', tmp_path / 'tf.txt'
    script = '\n'.join([
        'export ROS_MASTER_URI=http://localhost:%d' % port,
        'roslaunch -p %d gazebo_ros empty_world.launch 2>&1 &' % port,
        'rosparam set /robot_description -t %s 2>/dev/null || '
        '{ sleep 3; rosparam set /robot_description -t %s; }' % (urdf, urdf),
        'rosrun gazebo_ros spawn_model -urdf -param robot_description -model robot 2>&1',
        'timeout 60 rostopic echo -n 1 /gazebo_gui/robot_markers > %s' % markers,
        'timeout 60 rostopic echo -n 20 /tf > %s' % tf,
        'wait'])
    text = launch_with_viewer(tmp_path, script, 'gzclient: drawing robot')
    assert 'gzclient: drawing robot from /robot_description (5 links)' in text, text[-3000:]
    drawn = markers.read_text()
    # the links with visuals (the wheels have collisions only: Gazebo shows no wheel either),
    # each locked to its link's frame, which gzclient moves with /gazebo/link_states
    frames = sorted(set(line.split('"')[1] for line in drawn.splitlines()
                        if 'frame_id: "gazebo/' in line))
    assert frames == ['gazebo/robot/base_link', 'gazebo/robot/head'], drawn[:2000]
    assert drawn.count('frame_locked: True') == 2
    broadcast = tf.read_text()
    for link in ('base_link', 'head', 'left_wheel'):
        assert 'child_frame_id: "gazebo/robot/%s"' % link in broadcast

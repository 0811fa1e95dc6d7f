"""The GUI tools' stand-ins as plain functions (no master, no display):
rqt_image_view's topic and frames, smach_viewer's lines for a machine."""
from types import SimpleNamespace

import numpy as np
import pytest
from sensor_msgs.msg import CompressedImage, Image

from exp_assignment2.launch_surface.image_view import to_bgr, topic_of
from exp_assignment2.launch_surface.smach_view import describe, render


def test_the_topic_is_the_first_plain_argument():
    assert topic_of(['/robot/camera1/image_raw', '__name:=view']) == '/robot/camera1/image_raw'
    assert topic_of(['__name:=view', '__log:=x']) == ''


def test_frames_come_out_bgr():
    rgb = np.zeros((2, 3, 3), np.uint8)
    rgb[:, :, 0] = 255      # red
    out = to_bgr(Image(height=2, width=3, encoding='rgb8', step=9, data=rgb.tobytes()))
    assert out.shape == (2, 3, 3) and out[0, 0].tolist() == [0, 0, 255]
    import cv2
    ok, jpeg = cv2.imencode('.png', out)
    back = to_bgr(CompressedImage(format='png', data=jpeg.tobytes()))
    assert back[0, 0].tolist() == [0, 0, 255]
    with pytest.raises(ValueError, match="encoding '16UC1'"):
        to_bgr(Image(height=1, width=1, encoding='16UC1', step=2, data=b'\0\0'))


@pytest.mark.parametrize('argv,display,clock', [
    (['/robot/camera1/image_raw'], ':7', True),      # a window that shows frames
    ([], ':7', False),                               # no topic: nothing to show
    (['/robot/camera1/image_raw'], None, False),     # no display: no window
])
def test_rqt_image_view_takes_the_simulated_clock_only_for_a_window(argv, display, clock,
                                                                    monkeypatch):
    """/clock comes a thousand times a simulated second: a viewer that shows nothing
    does not subscribe to it (rospy's ``disable_rostime``)."""
    from exp_assignment2.launch_surface import image_view
    asked, shown = {}, []
    monkeypatch.setattr(image_view.rospy, 'init_node', lambda name, **kw: asked.update(kw))
    monkeypatch.setattr(image_view.rospy, 'myargv', lambda: ['rqt_image_view'] + argv)
    monkeypatch.setattr(image_view.rospy, 'signal_shutdown', lambda reason: None)
    monkeypatch.setattr(image_view.rospy, 'loginfo', lambda *a: None)
    monkeypatch.setattr(image_view, 'Stop', lambda: SimpleNamespace(wait=lambda: None))
    monkeypatch.setattr(image_view, '_show', lambda topic, where: shown.append(topic))
    if display:
        monkeypatch.setenv('DISPLAY', display)
    else:
        monkeypatch.delenv('DISPLAY', raising=False)
    assert image_view.main() == 0
    assert asked['disable_rostime'] is (not clock)
    assert shown == (argv if clock else [])


def test_a_machine_is_its_states_with_the_active_one_marked():
    structure = SimpleNamespace(path='/SM_ROOT', children=['KITCHEN', 'GARDEN'],
                                internal_outcomes=['go', 'go'],
                                outcomes_from=['KITCHEN', 'GARDEN'],
                                outcomes_to=['GARDEN', 'KITCHEN'], container_outcomes=['done'])
    status = SimpleNamespace(path='/SM_ROOT', active_states=['GARDEN'])
    lines = describe({'/SM_ROOT': structure}, {'/SM_ROOT': status})
    assert lines == [('/SM_ROOT  (outcomes: done)', False),
                     ('    KITCHEN   [go -> GARDEN]', False),
                     ('  > GARDEN   [go -> KITCHEN]', True)]
    assert render(lines).shape[0] > 3 * 20


def test_gzclient_finds_a_models_urdf_by_its_links_and_locks_visuals_to_them():
    import os
    from exp_assignment2.launch_surface import robot_drawing
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with open(os.path.join(here, 'fixtures', 'spawned_robot.urdf')) as f:
        text = f.read()
    params = {'/robot_description': text, '/robot2/robot_description': text,
              '/use_sim_time': True, '/broken_description': '<robot name="x"><link/></robot>'}
    found = robot_drawing.find_descriptions(sorted(params), params.get)
    assert sorted(found) == ['/robot2/robot_description', '/robot_description']
    links = {'base_link', 'left_wheel', 'right_wheel', 'head', 'cam_link'}
    assert robot_drawing.match(links, found)[0] == '/robot_description'
    assert robot_drawing.match(links - {'head'}, found) is None
    markers = robot_drawing.robot_markers('robot', found['/robot_description'])
    assert [(m.header.frame_id, m.frame_locked) for m in markers] == [
        ('gazebo/robot/base_link', True), ('gazebo/robot/head', True)]

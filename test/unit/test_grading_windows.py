"""The bookkeeping of a run's window pictures (exp_assignment2.grading.run.windows)
and their place on the page, with no display and no simulator."""
import json
import os

import pytest

from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.report import index as report
from exp_assignment2.grading.run import windows

DOG = profiles.load('dog')


def book(tmp_path, **limits):
    return windows.CaptureBook(str(tmp_path / 'display'), **limits)


def test_a_window_is_kept_when_it_changed_and_a_new_title_only_within_the_limit(tmp_path):
    b = book(tmp_path, max_windows=2)
    assert b.wants('camera', 1)
    b.add('camera', 10.0, b'jpeg', 1, (800, 800))
    assert not b.wants('camera', 1)         # the same pixels: nothing new on screen
    assert b.wants('camera', 2)
    b.add('mask', 10.0, b'jpeg', 7, (800, 800))
    assert not b.wants('third', 3) and not b.wants('third', 4) and not b.wants('fourth', 5)
    assert (b.left_out, b.left_out_count) == (['third', 'fourth'], 2)
    for tick in range(3):       # a thousand windows, seen again every period
        assert not any([b.admits('w%d' % i) for i in range(1000)])
    assert b.left_out_count == 1002 and len(b.left_out) == windows.LEFT_OUT_NAMED
    assert [w['title'] for w in b.windows] == ['camera', 'mask']


def test_past_the_pictures_limit_every_second_one_goes_and_the_newest_stays(tmp_path):
    b = book(tmp_path, max_pictures=4)
    names = [b.add('camera', float(t), b'x' * 10, t, (10, 10)) for t in range(5)]
    kept = [p['file'] for p in b.windows[0]['pictures']]
    assert kept == [names[0], names[2], names[4]]      # counted from the newest
    assert (b.thinned, b.period) == (1, 2.0)
    assert sorted(os.listdir(b.directory)) == sorted(kept)
    assert b.bytes == 30


def test_past_the_bytes_limit_it_thins_too(tmp_path):
    b = book(tmp_path, max_bytes=250)
    for t in range(3):
        b.add('camera', float(t), b'x' * 100, t, (10, 10))
    assert b.bytes <= 250 and b.thinned == 1
    assert len(b.windows[0]['pictures']) == 2


def test_what_is_written_is_read_back_and_only_its_own_files(tmp_path):
    b = book(tmp_path)
    b.add('<script>alert(1)</script>', 5.0, b'jpeg', 1, (3000, 200), scaled=True)
    b.write()
    with open(os.path.join(b.directory, 'windows.json')) as f:
        data = json.load(f)
    # a student who writes the index: paths out of the directory are not taken
    data['windows'][0]['pictures'] += [{'file': '../../record/run.json', 'wall': 6.0},
                                       {'file': '/etc/passwd', 'wall': 7.0},
                                       {'file': 'w0_99.jpg', 'wall': 8.0}]     # no such file
    data['windows'].append({'title': 'x' * 5000 + '\n', 'pictures': 'not a list'})
    with open(os.path.join(b.directory, 'windows.json'), 'w') as f:
        json.dump(data, f)
    shown = windows.read_windows(b.directory)
    assert [p['path'] for p in shown['windows'][0]['pictures']] == [
        os.path.join(b.directory, 'w0_1.jpg')]
    assert len(shown['windows'][1]['title']) == windows.MAX_TITLE
    assert windows.read_windows(str(tmp_path / 'nowhere')) is None
    notes = windows.limit_notes(shown)
    assert any('scaled down' in n for n in notes)


def test_wall_time_becomes_simulated_time_through_the_clock(tmp_path):
    record = tmp_path / 'record'
    record.mkdir()
    # real time for 10 s, then twice as fast; a reset to 0 at wall 120
    pairs = [(0.0, 100.0), (10.0, 110.0), (30.0, 120.0), (0.0, 120.5), (1.0, 121.5)]
    (record / 'clock.jsonl').write_text(''.join('[%s, %s]\n' % p for p in pairs) + 'junk\n')
    clock = windows.read_clock(str(record))
    assert windows.sim_time(clock, 105.0) == pytest.approx(5.0)
    assert windows.sim_time(clock, 115.0) == pytest.approx(20.0)
    assert windows.sim_time(clock, 50.0) == 0.0            # before the first: the first
    assert windows.sim_time(clock, 999.0) == 1.0           # after the last: the last
    assert windows.sim_time(clock, 121.0) == pytest.approx(0.5)
    assert windows.sim_time([], 5.0) is None


def test_each_moment_takes_the_picture_shown_last_before_it():
    clock = [(100.0, 0.0), (200.0, 100.0)]          # real time
    window = {'title': 'camera', 'pictures': [{'path': 'a', 'wall': 110.0},
                                              {'path': 'b', 'wall': 150.0}]}
    [(_, chosen, opened)] = windows.shown_at([window], clock, {'early': 5.0, 'first': 10.5,
                                                               'middle': 40.0, 'end': 100.0,
                                                               'no clock': None})
    # 'early' came before the window opened: its first picture, and when that was
    assert chosen == {'early': 'a', 'first': 'a', 'middle': 'a', 'end': 'b', 'no clock': 'b'}
    assert opened == {'early': 10.0}
    # at twice real time a period of 1 wall s is 2 simulated s: a picture 1.5 s
    # after the moment is the first that could show it
    fast = [(100.0, 0.0), (150.0, 100.0)]
    [(_, chosen, opened)] = windows.shown_at([window], fast, {'before': 18.5,
                                                              'long before': 17.0})
    assert chosen == {'before': 'a', 'long before': 'a'} and opened == {'long before': 20.0}
    [(_, chosen, opened)] = windows.shown_at([dict(window, pictures=[])], clock, {'end': 9.0})
    assert chosen == {'end': None} and opened == {}
    assert windows.pace(fast) == 2.0 and windows.pace([]) == 1.0


def test_the_page_shows_each_window_by_its_title_beside_the_camera(tmp_path):
    runs = tmp_path / 'runs'
    record = runs / 'ann' / 'record'
    (record / 'frames').mkdir(parents=True)
    import cv2
    import numpy
    frame = numpy.zeros((60, 80, 3), numpy.uint8)
    for t in (2.0, 9.0):
        cv2.imwrite(str(record / 'frames' / ('camera1_%08.2f.jpg' % t)), frame)
    (record / 'clock.jsonl').write_text('[0.0, 1000.0]\n[10.0, 1010.0]\n')
    with open(str(record / 'truth.jsonl'), 'w') as f:
        for i in range(100):        # closest to the ball at 2 s
            f.write(json.dumps({'kind': 'state', 't': i / 10, 'joints': {}, 'models': {
                'robot': [4 - abs(i - 20) / 20, 0, 0, 0], 'ball': [4, 0, 0.5, 0]}}) + '\n')
    with open(str(record / 'run.json'), 'w') as f:
        json.dump({'name': 'ann', 'label': 'ann', 'verdict': 'passed', 'checks': [],
                   'reason': '', 'commands': [], 'truth': {'sim_time': 10.0}}, f)
    b = windows.CaptureBook(str(runs / 'ann' / 'work' / 'display'), max_windows=1)
    shown = []
    for wall, grey in ((1003.0, 50), (1008.5, 200)):    # at 3 and 8.5 simulated s
        ok, jpeg = cv2.imencode('.jpg', numpy.full((60, 80, 3), grey, numpy.uint8))
        shown.append(b.add('my <camera> & "ball"', wall, jpeg.tobytes(), grey, (80, 60)))
    b.wants('1000 windows', 2)
    b.write()
    report.write(str(tmp_path), DOG)
    page = (tmp_path / 'pages' / 'ann.html').read_text()
    assert '<th>window &ldquo;my &lt;camera&gt; &amp; &quot;ball&quot;&rdquo;</th>' in page
    assert 'my <camera>' not in page
    # at each moment, the picture shown last before it, as a file beside the page:
    # at the closest approach (2 s), the one of 3 s (taken within a second of it);
    # at the end (9 s), the one of 8.5 s
    for moment, picture in (('closest_approach', shown[0]), ('end', shown[1])):
        src = 'img/ann_window0_%s.jpg' % moment
        assert 'src="%s"' % src in page
        with open(str(tmp_path / 'pages' / src), 'rb') as copy, \
                open(os.path.join(b.directory, picture), 'rb') as original:
            assert copy.read() == original.read(), moment
    assert '1 more windows opened and were not captured' in page


def test_the_display_and_the_viewers_it_makes_draw_have_their_own_share_of_cpu():
    from exp_assignment2.grading.run import cpu
    kinds = {command: cpu.kind(command) for command in (
        'Xvfb -displayfd 4 -screen 0 1920x1080x24',
        '/usr/bin/python3 /r/src/exp_assignment2/grading/run/display.py capture :0 /w/display',
        '/usr/bin/python3 /ws/src/gazebo_ros/scripts/gzclient __name:=gazebo_gui',
        'rviz -d /r/gazebo_ros/rviz/gzclient.rviz __name:=gazebo_gui_rviz',
        '/usr/bin/python3 /w/overlay/devel/lib/my_dog/dog.py',
        '/usr/bin/python3 /ws/devel/lib/exp_assignment2/simulator.py __name:=simulator')}
    assert list(kinds.values()) == ['display', 'display', 'viewer', 'viewer', 'student',
                                    'simulator']


def test_no_xvfb_is_a_display_error(tmp_path, monkeypatch):
    """(The verdict it leads to, grader_error, is test_grading_verdicts.py's 'no display'.)"""
    from exp_assignment2.grading.run import display
    monkeypatch.setenv('PATH', str(tmp_path))          # no Xvfb here
    with pytest.raises(display.DisplayError, match='Xvfb could not start'):
        display.start(str(tmp_path / 'display'))

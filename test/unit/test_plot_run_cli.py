"""plot_run.py as a user runs it: errors, and the real script on the short
recorded bags in test/data, looking at the picture's pixels. Needs Debian's
rosbag and matplotlib, no master and no catkin build: rosbag makes the
message classes from the bag itself."""
import contextlib
import io
import os
import subprocess

import pytest

from exp_assignment2.nodes import plot_run

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(REPO, 'test', 'data')
SCRIPT = os.path.join(REPO, 'scripts', 'plot_run.py')


# --- errors -------------------------------------------------------------------

def run_main(argv):
    """main() in-process: (exit code, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = plot_run.main(argv)
        except SystemExit as e:
            code = e.code
    return code, out.getvalue(), err.getvalue()


def one_error_line(err, words):
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith('plot_run.py: error: ') and words in lines[0], err


def test_missing_and_unreadable_files_exit_2_with_one_line(tmp_path):
    code, out, err = run_main([str(tmp_path / 'nothing.bag'), '-o', str(tmp_path / 'x.png')])
    assert code == 2 and out == ''
    one_error_line(err, 'no such bag file')
    pytest.importorskip('rosbag')
    (tmp_path / 'text.bag').write_text('not a bag\n')
    code, _, err = run_main([str(tmp_path / 'text.bag'), '-o', str(tmp_path / 'x.png')])
    assert code == 2
    one_error_line(err, 'not a readable bag')
    with open(os.path.join(DATA, 'dog_short.bag'), 'rb') as f:   # a recording cut short
        (tmp_path / 'cut.bag').write_bytes(f.read(40000))
    code, _, err = run_main([str(tmp_path / 'cut.bag'), '-o', str(tmp_path / 'x.png')])
    assert code == 2
    one_error_line(err, 'rosbag reindex')
    assert not (tmp_path / 'x.png').exists()


def test_a_bag_of_neither_scenario_exits_2(tmp_path):
    rosbag = pytest.importorskip('rosbag')
    from std_msgs.msg import String
    path = str(tmp_path / 'chatter.bag')
    with rosbag.Bag(path, 'w') as bag:
        bag.write('/chatter', String('hello'))
    code, _, err = run_main([path, '-o', str(tmp_path / 'x.png')])
    assert code == 2
    one_error_line(err, 'neither /robot/odom')


# --- the real script on recorded bags -----------------------------------------

def load_png(path):
    """The PNG as an (h, w, 3) int array."""
    from matplotlib import image
    return (image.imread(path)[..., :3] * 255).round().astype(int)


def region(png, rect):
    """The pixels inside a figure-fraction rectangle (left, bottom, width, height)."""
    h, w = png.shape[:2]
    left, bottom, width, height = rect
    return png[int(h * (1 - bottom - height)):int(h * (1 - bottom)),
               int(w * left):int(w * (left + width))]


def where(pixels, colour, tol=4):
    """Mask of the pixels of ``colour`` ('#rrggbb')."""
    import numpy
    rgb = numpy.array([int(colour[i:i + 2], 16) for i in (1, 3, 5)])
    return numpy.abs(pixels - rgb).max(axis=-1) <= tol


def count(pixels, colour):
    return int(where(pixels, colour).sum())


def mean_column(pixels, colour):
    return where(pixels, colour).nonzero()[1].mean()


@pytest.fixture(scope='module')
def dog(tmp_path_factory):
    """The installed script as a user runs it: (completed process, PNG pixels)."""
    pytest.importorskip('rosbag')
    png = str(tmp_path_factory.mktemp('dog') / 'dog.png')
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [os.path.join(REPO, 'src')] + [p for p in [os.environ.get('PYTHONPATH')] if p]))
    proc = subprocess.run(['/usr/bin/python3', SCRIPT, os.path.join(DATA, 'dog_short.bag'),
                           '-o', png], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return proc, load_png(png)


@pytest.fixture(scope='module')
def miro(tmp_path_factory):
    """main() in-process on the MiRo bag: (stdout, PNG pixels)."""
    pytest.importorskip('rosbag')
    png = str(tmp_path_factory.mktemp('miro') / 'miro.png')
    code, out, err = run_main([os.path.join(DATA, 'miro_short.bag'), '-o', png])
    assert code == 0, err
    return out, load_png(png)


def test_dog_summary(dog):
    out = dog[0].stdout
    assert 'dog_short.bag: scenario A (dog and ball)' in out
    for state in ('SLEEP', 'NORMAL', 'PLAY'):
        assert '  %s ' % state in out
    assert '2 state changes' in out and 'ball hidden: 1 stretches' in out
    assert 'wrote ' in out and dog[0].stderr == ''


def test_dog_picture(dog):
    from exp_assignment2.run_figure import (BALL_COLOUR, BALL_HIDDEN_COLOUR, MAP_RECT,
                                            STATE_COLOURS, TIMELINE_RECT, WALL_COLOUR)
    png = dog[1]
    assert png.shape == (1100, 1400, 3)
    world, timeline = region(png, MAP_RECT), region(png, TIMELINE_RECT)
    assert count(world, WALL_COLOUR) > 4 * 500 * 5       # four walls, 500+ px long
    # the dog slept (to the kennel) and played; NORMAL was turning on the spot
    assert count(world, STATE_COLOURS['SLEEP']) > 300
    assert count(world, STATE_COLOURS['PLAY']) > 100
    assert count(world, BALL_COLOUR) > 300
    assert count(world, BALL_HIDDEN_COLOUR) > 20         # its dots
    for colour in list(STATE_COLOURS.values()) + [BALL_HIDDEN_COLOUR]:
        assert count(timeline, colour) > 500, colour
    # SLEEP, then NORMAL, then PLAY from left to right
    columns = [mean_column(timeline, STATE_COLOURS[s]) for s in ('SLEEP', 'NORMAL', 'PLAY')]
    assert columns == sorted(columns)


def test_miro_summary(miro):
    out = miro[0]
    assert 'miro_short.bag: scenario B (MiRo)' in out
    assert '2 state changes' in out and '6 arrivals, 2 gestures, 1 words' in out


def test_miro_picture(miro):
    from exp_assignment2.run_figure import (HOME_COLOUR, MAP_RECT, PERSON_COLOUR, STATE_COLOURS,
                                            TIMELINE_RECT)
    png = miro[1]
    assert png.shape == (1100, 1400, 3)
    world, timeline = region(png, MAP_RECT), region(png, TIMELINE_RECT)
    for state, colour in STATE_COLOURS.items():
        assert count(world, colour) > 300, state
        assert count(timeline, colour) > 500, state
    assert count(world, HOME_COLOUR) > 100
    assert count(world, PERSON_COLOUR) > 100            # the person, where they pointed

"""The run's display and its window capture on a real Xvfb (no ROS, no sandbox):
windows are read through the X server's shared memory (grading.run.xshm),
byte for byte what GetImage reads, a window gone between listing and reading
costs nothing but its picture, and the capture keeps each window's picture."""
import os
import shutil
import signal
import time

import pytest

pytest.importorskip('Xlib')
if not shutil.which('Xvfb'):
    pytest.skip('no Xvfb', allow_module_level=True)
from Xlib import X  # noqa: E402
from Xlib import display as xdisplay  # noqa: E402

from exp_assignment2.grading.run import display, windows, xshm  # noqa: E402

COLOUR = (40, 160, 220)          # B, G, R of the test's window


@pytest.fixture
def screen(tmp_path):
    processes, name = display.start(str(tmp_path / 'display'))
    try:
        yield name, str(tmp_path / 'display')
    finally:
        for process in processes:
            process.send_signal(signal.SIGTERM)
        for process in processes:
            try:
                process.wait(timeout=10)
            except Exception:
                process.kill()


def window(name, title, size=(320, 200), colour=COLOUR):
    """A mapped top-level window at (0, 0) filled with ``colour``, titled ``title``."""
    conn = xdisplay.Display(name)
    screen = conn.screen()
    pixel = colour[2] << 16 | colour[1] << 8 | colour[0]
    win = screen.root.create_window(0, 0, size[0], size[1], 0, screen.root_depth,
                                    background_pixel=pixel)
    win.set_wm_name(title)
    win.map()
    conn.sync()
    return conn, win


def test_shared_memory_reads_what_get_image_reads_and_a_gone_window_is_none(screen):
    name, _ = screen
    conn, win = window(name, 'camera')
    time.sleep(0.3)
    reader = xshm.ShmReader(name)
    try:
        got = reader.read(win.id, 320, 200)
        expected = win.get_image(0, 0, 320, 200, X.ZPixmap, 0xffffffff).data
        assert got == expected and len(got) == 320 * 200 * 4
        assert got[:3] == bytes(COLOUR)
        assert reader.read(win.id, 1500, 900) is None     # larger than the window
        small = reader.read(win.id, 31, 7)       # a smaller part: rows of its own width
        assert small == win.get_image(0, 0, 31, 7, X.ZPixmap, 0xffffffff).data
        gone = win.id
        win.destroy()
        conn.sync()
        assert reader.read(gone, 320, 200) is None       # no X error ends the process
        _, other = window(name, 'other', (640, 480))     # a larger segment made
        assert reader.read(other.id, 640, 480)[:3] == bytes(COLOUR)
    finally:
        reader.close()


def test_the_capture_keeps_each_window_s_picture(screen):
    name, directory = screen
    # no window manager: the second opens over the first, which is read whole all the same
    kept = [window(name, 'camera'), window(name, 'the state machine', (200, 150), (0, 0, 255))]
    deadline, seen = time.monotonic() + 20, {}
    while time.monotonic() < deadline and len(seen) < 2:
        time.sleep(0.5)
        shown = windows.read_windows(directory) or {'windows': []}
        seen = {w['title']: w['pictures'] for w in shown['windows'] if w['pictures']}
    assert sorted(seen) == ['camera', 'the state machine'], seen
    import cv2
    picture = cv2.imread(seen['camera'][0]['path'])
    assert picture.shape == (200, 320, 3)
    for y, x in ((100, 160), (10, 10)):         # beside the other, and under it
        assert [abs(int(a) - b) <= 3 for a, b in zip(picture[y, x], COLOUR)] == [True] * 3
    assert len(kept) == 2       # their connections open until here: their windows too
    with open(os.path.join(directory, 'windows.json')) as f:
        assert 'shared memory' not in f.read()      # read through it here


def test_a_window_s_picture_is_its_pixels_in_blue_green_red_and_contiguous():
    numpy = pytest.importorskip('numpy')
    rng = numpy.random.default_rng(3)
    zpixmap = rng.integers(0, 256, (5, 7, 4), dtype=numpy.uint8)   # B, G, R, unused
    pixels, scaled = display._picture(zpixmap.tobytes(), 6, 5)     # the window's left 6 px
    assert not scaled and pixels.flags['C_CONTIGUOUS']
    assert pixels.shape == (5, 6, 3) and (pixels == zpixmap[:, :6, :3]).all()
    assert display._picture(b'\0' * 10, 6, 5) == (None, False)

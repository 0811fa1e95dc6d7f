"""A run's own display, inside its sandbox (no ROS).

:func:`start` starts Xvfb on the sandbox's own ``/tmp`` and network
namespace (its sockets, abstract and in ``/tmp/.X11-unix``, are the run's
only: no two runs share a display), then this file as the capture process:

    /usr/bin/python3 display.py capture DISPLAY DIRECTORY

which keeps pictures of the top-level windows in DIRECTORY
(:class:`~exp_assignment2.grading.run.windows.CaptureBook`: what changed, once
per period, bounded). With no window manager windows open where they ask,
on top of each other: the Composite extension keeps each window's own
contents off screen, and each is read from there, whole whatever covers it.
Xvfb's and the capture's output are in DIRECTORY/display.log.
"""
import os
import select
import signal
import subprocess
import sys
import time
import zlib

SCREEN = (1920, 1080)
START_WAIT = 10.0        # wall s for Xvfb to say its display


class DisplayError(Exception):
    """No display could be made (the grader's fault, never the student's)."""


def start(directory, timeout=START_WAIT):
    """([capture, Xvfb] processes, ':N'), each in a session of its own."""
    os.makedirs(directory, exist_ok=True)
    try:        # Xvfb makes it only as root; the sandbox's /tmp is the run's
        os.makedirs('/tmp/.X11-unix', exist_ok=True)
        os.chmod('/tmp/.X11-unix', 0o1777)
    except OSError:
        pass
    read_fd, write_fd = os.pipe()
    log = open(os.path.join(directory, 'display.log'), 'ab')
    try:
        xvfb = subprocess.Popen(
            ['Xvfb', '-displayfd', str(write_fd), '-screen', '0', '%dx%dx24' % SCREEN,
             '-nolisten', 'tcp', '-noreset'], pass_fds=(write_fd,), stdin=subprocess.DEVNULL,
            stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    except OSError as exc:
        os.close(read_fd)
        log.close()
        raise DisplayError('Xvfb could not start: %s' % (exc.strerror or exc))
    finally:
        os.close(write_fd)
    number, deadline = b'', time.monotonic() + timeout
    try:
        while not number.endswith(b'\n') and time.monotonic() < deadline:
            ready, _, _ = select.select([read_fd], [], [], max(0.0, deadline - time.monotonic()))
            chunk = os.read(read_fd, 16) if ready else b''
            if not chunk:
                break
            number += chunk
    finally:
        os.close(read_fd)
    if not number.strip().isdigit():
        xvfb.kill()
        xvfb.wait()
        log.close()
        raise DisplayError('Xvfb gave no display within %g s (exit %s; %s)' % (
            timeout, xvfb.returncode, os.path.join(directory, 'display.log')))
    name = ':' + number.strip().decode()
    try:
        capture = subprocess.Popen([sys.executable, os.path.realpath(__file__), 'capture', name,
                                    directory], stdin=subprocess.DEVNULL, stdout=log,
                                   stderr=subprocess.STDOUT, start_new_session=True)
    except OSError as exc:
        xvfb.kill()
        raise DisplayError('the window capture could not start: %s' % (exc.strerror or exc))
    finally:
        log.close()
    return [capture, xvfb], name


def _title(window, net_wm_name, utf8):
    from Xlib import error
    try:
        title = window.get_full_text_property(net_wm_name, utf8)
        return title if title else window.get_wm_name()
    except (error.XError, UnicodeError):
        return None


def _picture(data, width, height):
    """(BGR pixels, scaled?) of a ZPixmap of 32 bits a pixel, or None."""
    import cv2
    import numpy
    from exp_assignment2.grading.run.windows import MAX_SIDE
    if height == 0 or len(data) < height * width * 4:
        return None, False
    pixels = numpy.frombuffer(data, numpy.uint8)
    pixels = pixels[:height * (len(pixels) // height)].reshape(height, -1, 4)[:, :width]
    # one pass to contiguous BGR: the JPEG of a strided 3-of-4-bytes view cost 4.6 ms
    # at 800 x 800, of this 1.4 (and the same bytes)
    pixels = cv2.cvtColor(pixels, cv2.COLOR_BGRA2BGR)
    if max(width, height) <= MAX_SIDE:
        return pixels, False
    scale = float(MAX_SIDE) / max(width, height)
    return cv2.resize(pixels, (max(1, int(width * scale)), max(1, int(height * scale))),
                      interpolation=cv2.INTER_AREA), True


def _reader(name, book):
    """read(window, width, height) -> its pixels' bytes (None: gone): through
    shared memory (:mod:`.xshm`), else python-xlib's GetImage (the note says why)."""
    from Xlib import X
    from exp_assignment2.grading.run import xshm
    try:
        shm = xshm.ShmReader(name)
        return lambda window, width, height: shm.read(window.id, width, height)
    except xshm.ShmUnavailable as exc:
        book.notes.append('windows read without shared memory (%s)' % exc)
    return lambda window, width, height: window.get_image(
        0, 0, width, height, X.ZPixmap, 0xffffffff).data


def capture(name, directory):
    """Keep pictures of the display's windows until it ends or a signal comes."""
    import cv2
    from Xlib import X, error
    from Xlib import display as xdisplay
    from Xlib.ext import composite
    from exp_assignment2.grading.run.windows import MAX_LOOK, MAX_READ, CaptureBook
    book = CaptureBook(directory)
    display = xdisplay.Display(name)
    read = _reader(name, book)
    root = display.screen().root
    if display.has_extension('Composite'):
        # manual: each window is kept off screen and never drawn onto the screen
        # (nobody watches it); automatic redirection also composited every frame
        # of a student's imshow onto it, half of Xvfb's work (measured: 0.038
        # of a core for an 800 x 800 window at 30 Hz, 0.023 without)
        composite.redirect_subwindows(root, composite.RedirectManual)
    else:
        book.notes.append('no Composite extension: a window covered by another shows it')
    book.write()
    net_wm_name, utf8 = display.intern_atom('_NET_WM_NAME'), display.intern_atom('UTF8_STRING')
    running, looked_past = [True], False
    signal.signal(signal.SIGTERM, lambda *_: running.__setitem__(0, False))
    signal.signal(signal.SIGINT, lambda *_: running.__setitem__(0, False))
    while running[0]:
        now, seen = time.time(), set()
        try:
            children = root.query_tree().children
        except error.ConnectionClosedError:
            break
        if len(children) > MAX_LOOK and not looked_past:
            looked_past = True
            book.notes.append('%d top-level windows at once: only the first %d were looked at'
                              % (len(children), MAX_LOOK))
            book.dirty = True
        for window in children[:MAX_LOOK]:
            try:
                if window.get_attributes().map_state != X.IsViewable:
                    continue
                title = _title(window, net_wm_name, utf8)
                if title in seen or not book.admits(title):    # one picture a title
                    continue
                geometry = window.get_geometry()
                width, height = min(geometry.width, MAX_READ), min(geometry.height, MAX_READ)
                data = read(window, width, height)
            except error.ConnectionClosedError:
                running[0] = False
                break
            except error.XError:        # it went away meanwhile
                continue
            if data is None:            # it went away meanwhile (the shared memory's read)
                continue
            seen.add(title)
            digest = zlib.crc32(data)
            if not book.wants(title, digest):
                continue
            pixels, scaled = _picture(data, width, height)
            if pixels is None:
                continue
            ok, jpeg = cv2.imencode('.jpg', pixels, [cv2.IMWRITE_JPEG_QUALITY, 80])
            if ok:
                book.add(title, now, jpeg.tobytes(), digest, (geometry.width, geometry.height),
                         scaled=scaled, cut=(width, height) != (geometry.width, geometry.height))
        if book.dirty:
            book.write()
        deadline = now + book.period
        while running[0] and time.time() < deadline:
            time.sleep(min(0.1, max(0.0, deadline - time.time())))
    book.write()


if __name__ == '__main__':
    # this repository's src first: the student's package may be called exp_assignment2 too
    # src/exp_assignment2/grading/run/display.py -> src, where the library is
    sys.path[0] = os.path.realpath(__file__).rsplit(os.sep + 'exp_assignment2' + os.sep, 1)[0]
    if len(sys.argv) == 4 and sys.argv[1] == 'capture':
        capture(sys.argv[2], sys.argv[3])
    else:
        sys.exit('usage: display.py capture DISPLAY DIRECTORY')

"""How many camera frames a submission's robot will have drawn, read from its
robot files before it runs (no ROS).

A run's cost follows its camera. The simulator draws, encodes and sends every
frame: 0.0074 of a core per 800 x 800 frame a second on a real class. A student's
node that watches the camera decodes and searches every frame too. A class whose
robots carry different cameras (the course's 800 x 800 at 30 Hz, this package's
320 x 240 at 15 Hz) has runs of 0.6 and of 0.15 of a core. Counted at one median,
the cheap ones never started beside the dear ones (run.admission).

:func:`frames` gives the most frames a second, counted in frames of 800 x 800,
of the ``<sensor type="camera">`` elements (``update_rate``, ``image``
``width`` x ``height``) in the robot files (``.urdf``, ``.xacro``, ``.gazebo``,
``.sdf``) of the packages a run builds. It is None when no camera is read. A
value that is a xacro expression (``${...}``) is not evaluated, and that camera
is not read.
"""
import math
import os
import re

from exp_assignment2.grading.entry.reading import of_built

ROBOT_FILES = ('.urdf', '.xacro', '.gazebo', '.sdf')
FRAME_PIXELS = 800 * 800        # a frame counted: the course camera's
MOST_FILES = 200                # robot files read of one submission
MOST_BYTES = 512 * 1024         # of one file
CAMERA = re.compile(r'\btype\s*=\s*["\']camera["\']')


def _value(text, tag):
    """The number in the first ``<tag>...</tag>`` of ``text``, or None."""
    start = text.find('<%s>' % tag)
    end = text.find('</%s>' % tag, start)
    if start < 0 or end < 0:
        return None
    try:
        return float(text[start + len(tag) + 2:end].strip())
    except ValueError:          # a xacro expression, or anything else: not read
        return None


def sensors(text):
    """The bodies of the ``<sensor type="camera">`` elements of ``text`` (found
    with ``find``, not a regular expression that could backtrack over a file)."""
    at = text.find('<sensor')
    while at >= 0:
        close = text.find('>', at)
        end = text.find('</sensor>', close) if close >= 0 else -1
        if end < 0:             # no sensor closes after this: none is read further on
            return
        if CAMERA.search(text, at, close):
            yield text[close + 1:end]
        at = text.find('<sensor', end)      # each part of the text is read once


def in_text(text):
    """[frames of 800 x 800 a second] of each camera sensor read in ``text``."""
    found = []
    for body in sensors(text):
        rate, width, height = (_value(body, tag) for tag in ('update_rate', 'width', 'height'))
        values = (rate, width, height)
        if None in values or not all(math.isfinite(v) and v > 0 for v in values):
            continue
        found.append(rate * width * height / FRAME_PIXELS)
    return found


def frames(root, folders):
    """The most frames of 800 x 800 a second a camera in the robot files of
    ``folders`` (relative to ``root``) declares, or None (see the module)."""
    most, read = None, 0
    for folder in folders:
        for where, dirs, files in os.walk(os.path.join(root, folder)):
            dirs[:] = sorted(d for d in dirs if not d.startswith('.'))
            for name in sorted(files):
                if not name.endswith(ROBOT_FILES):
                    continue
                path = os.path.join(where, name)
                if read >= MOST_FILES:
                    return most
                read += 1
                try:
                    if not os.path.isfile(path) or os.path.getsize(path) > MOST_BYTES:
                        continue
                    with open(path, encoding='utf-8', errors='replace') as f:
                        text = f.read()
                except OSError:
                    continue
                for value in in_text(text):
                    most = value if most is None else max(most, value)
    return most


def of_runs(runs, copies):
    """{name: frames a second} of the submissions of ``runs`` whose built
    packages declare a camera (entry.reading.of_built)."""
    return of_built(runs, copies, frames)

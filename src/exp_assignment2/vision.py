"""Finding the green ball in a camera image (plain OpenCV, no ROS).

The pipeline of the original: blur 11x11, HSV, in-range (50, 50, 20) to
(70, 255, 255), erode x2, dilate x2, largest external contour, minimum
enclosing circle, centroid. A ball counts when its radius exceeds 10 px at
800 px of image width, scaled to the actual width.

The same pipeline can run on an image decoded at a fraction of its size
(``decode_jpeg(data, scale)``: libjpeg scales while it decodes, which costs
a fraction of a full decode): the blur, the erosion and the halo shrink with
it, and the ball is given back in the full image's pixels, so the thresholds
stay those of the full image. At 800 px, scale 2 finds the same ball within
a pixel (test_vision.py) for a quarter of the work.

OpenCV runs single-threaded in a process that imports this module: a node
decodes and detects in its camera callback, beside the simulator and the
other nodes on the same cores, where OpenCV's worker threads cost more CPU
than they save wall time (detection at 400 px: 2.24 ms of CPU a frame with
2 threads, 1.60 ms with one; 320 px: 1.52 and 1.23 ms).

JPEGs are made by PyPI's simplejpeg (libjpeg-turbo, as OpenCV's) where it is
installed: the same quality and 4:2:0 chroma as ``cv2.imencode`` (and
compressed_image_transport) for a quarter less CPU (an 800 x 800 camera
frame: 1.03 ms against 1.35, measured side by side), which the simulator
pays 30 times a simulated second for the course's camera. Without it,
OpenCV encodes.
"""
from collections import namedtuple

import cv2
import numpy as np

try:
    import simplejpeg
except ImportError:         # OpenCV encodes (tools/run installs simplejpeg)
    simplejpeg = None

cv2.setNumThreads(1)

GREEN_LOWER = (50, 50, 20)
GREEN_UPPER = (70, 255, 255)
REFERENCE_WIDTH = 800.0
MIN_RADIUS_AT_REFERENCE = 10.0
# The 11x11 Gaussian (sigma 2 px) spreads green about one sigma past the
# ball's edge before the in-range threshold: the enclosing circle is that much
# too big. Subtracting it makes the radius estimate the ball's own.
BLUR_HALO_PX = 2.0

Ball = namedtuple('Ball', 'x y radius cx cy')
Ball.__doc__ = """A detected ball: enclosing circle (x, y, radius) and centroid (cx, cy), px."""


DECODE_FLAGS = {1: cv2.IMREAD_COLOR, 2: cv2.IMREAD_REDUCED_COLOR_2,
                4: cv2.IMREAD_REDUCED_COLOR_4, 8: cv2.IMREAD_REDUCED_COLOR_8}


def decode_jpeg(data, scale=1):
    """BGR image from JPEG bytes (a CompressedImage's data), at 1/``scale``
    of its size (1, 2, 4 or 8), or None when they are not an image (empty,
    truncated, garbage)."""
    if not len(data):
        return None              # cv2.imdecode raises on an empty buffer
    try:
        return cv2.imdecode(np.frombuffer(data, np.uint8), DECODE_FLAGS[scale])
    except (cv2.error, TypeError, ValueError):
        return None


def vision_scale(width, least=400):
    """The largest decode scale that leaves at least ``least`` px of width."""
    return max([s for s in DECODE_FLAGS if width / s >= least] or [1])


def encode_jpeg(bgr, quality=80):
    """JPEG bytes of a BGR image (4:2:0 chroma, as OpenCV's and libjpeg's default)."""
    if simplejpeg is not None and isinstance(bgr, np.ndarray) and bgr.dtype == np.uint8 \
            and bgr.ndim == 3 and bgr.shape[2] == 3 and bgr.flags.c_contiguous \
            and 1 <= quality <= 100:
        return simplejpeg.encode_jpeg(bgr, quality=int(quality), colorspace='BGR',
                                      colorsubsampling='420')
    ok, buf = cv2.imencode('.jpg', bgr, [int(cv2.IMWRITE_JPEG_QUALITY), int(quality)])
    if not ok:
        raise ValueError('JPEG encoding failed')
    return buf.tobytes()


class BallDetector(object):
    """Detects the largest green blob; ignores blobs below the radius threshold."""

    def __init__(self, min_radius_at_800=MIN_RADIUS_AT_REFERENCE):
        self.min_radius_at_800 = float(min_radius_at_800)
        self.last_mask = None

    def min_radius(self, width):
        """The threshold (px) for an image ``width`` px wide."""
        return self.min_radius_at_800 * width / REFERENCE_WIDTH

    def detect(self, bgr, scale=1):
        """Return a :class:`Ball` or None for a BGR image; ``bgr`` may be the
        camera image decoded at 1/``scale`` of its size (see the module
        docstring): the ball is in the full image's pixels."""
        if scale == 1:
            blurred = cv2.GaussianBlur(bgr, (11, 11), 0)      # the original's
        else:
            blurred = cv2.GaussianBlur(bgr, (0, 0), 2.0 / scale)
        hsv = cv2.cvtColor(blurred, cv2.COLOR_BGR2HSV)
        mask = cv2.inRange(hsv, GREEN_LOWER, GREEN_UPPER)
        steps = max(1, int(round(2 / scale)))        # erode/dilate 2 px of the full image
        mask = cv2.erode(mask, None, iterations=steps)
        mask = cv2.dilate(mask, None, iterations=steps)
        self.last_mask = mask
        contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
        if not contours:
            return None
        largest = max(contours, key=cv2.contourArea)
        (x, y), radius = cv2.minEnclosingCircle(largest)
        m = cv2.moments(largest)
        cx, cy = (m['m10'] / m['m00'], m['m01'] / m['m00']) if m['m00'] > 0 else (x, y)
        # a pixel i of the reduced image covers the full image's [s i, s i + s)
        full = lambda v: scale * (v + 0.5) - 0.5   # noqa: E731
        radius = max(radius * scale - BLUR_HALO_PX, 0.0)
        if radius <= self.min_radius(bgr.shape[1] * scale):
            return None
        return Ball(full(x), full(y), float(radius), full(cx), full(cy))


def annotate(bgr, ball):
    """Draw the ball's circle and centroid on ``bgr`` in place (as the original)."""
    if ball is not None:
        cv2.circle(bgr, (int(ball.x), int(ball.y)), int(ball.radius), (0, 255, 255), 2)
        cv2.circle(bgr, (int(ball.cx), int(ball.cy)), 5, (0, 0, 255), -1)
    return bgr

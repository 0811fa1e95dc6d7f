"""The ball detector on synthetic images with known answers."""
import cv2
import numpy as np
import pytest

from exp_assignment2.vision import BallDetector, annotate, decode_jpeg, encode_jpeg, vision_scale

GREEN = (0, 204, 0)   # BGR of the ball's RGB (0, 0.8, 0)


def scene(width=320, height=320, ball=None):
    img = np.full((height, width, 3), (200, 200, 200), np.uint8)
    img[height // 2:] = (90, 90, 90)
    if ball is not None:
        cv2.circle(img, ball[:2], ball[2], GREEN, -1)
    return img


@pytest.mark.parametrize('centre,radius', [((160, 160), 40), ((100, 220), 25), ((250, 80), 60)])
def test_ball_found_within_2px(centre, radius):
    ball = BallDetector().detect(scene(ball=(centre[0], centre[1], radius)))
    assert ball is not None
    assert abs(ball.x - centre[0]) <= 2 and abs(ball.y - centre[1]) <= 2
    assert abs(ball.cx - centre[0]) <= 2 and abs(ball.cy - centre[1]) <= 2
    assert abs(ball.radius - radius) <= 2


def test_no_ball_no_detection():
    assert BallDetector().detect(scene()) is None


def test_ball_cut_by_the_image_edge_is_still_found():
    ball = BallDetector().detect(scene(ball=(0, 160, 50)))
    assert ball is not None
    assert ball.cx < 30
    assert abs(ball.cy - 160) <= 2


def test_tiny_blob_below_threshold_is_ignored():
    # 10 px at 800 px wide is 4 px at 320: a 3 px blob does not count
    detector = BallDetector()
    assert detector.min_radius(320) == pytest.approx(4.0)
    assert detector.detect(scene(ball=(160, 160, 3))) is None
    assert detector.detect(scene(ball=(160, 160, 8))) is not None


def test_threshold_scales_with_width():
    detector = BallDetector()
    assert detector.min_radius(800) == pytest.approx(10.0)
    assert detector.detect(scene(800, 800, ball=(400, 400, 9))) is None
    assert detector.detect(scene(800, 800, ball=(400, 400, 20))) is not None


def test_largest_blob_wins():
    img = scene(ball=(80, 80, 20))
    cv2.circle(img, (240, 240), 45, GREEN, -1)
    ball = BallDetector().detect(img)
    assert abs(ball.x - 240) <= 2 and abs(ball.radius - 45) <= 2


def test_other_colours_are_not_the_ball():
    img = scene()
    cv2.circle(img, (160, 160), 50, (200, 30, 30), -1)    # blue
    cv2.circle(img, (60, 60), 30, (30, 30, 200), -1)      # red
    assert BallDetector().detect(img) is None


def test_detection_survives_jpeg_and_annotation_draws():
    img = scene(ball=(200, 150, 35))
    decoded = decode_jpeg(encode_jpeg(img, 80))
    ball = BallDetector().detect(decoded)
    assert abs(ball.x - 200) <= 2 and abs(ball.y - 150) <= 2
    out = annotate(decoded.copy(), ball)
    assert (out != decoded).any()


@pytest.mark.parametrize('centre,radius', [((400, 400), 200), ((130, 610), 60), ((700, 90), 25),
                                           ((400, 430), 12), ((5, 400), 80)])
def test_a_half_scale_decode_finds_the_same_ball_in_full_image_pixels(centre, radius):
    """The state machine's cheap path at 800 px: decode at half size, detect, scale back."""
    jpeg = encode_jpeg(scene(800, 800, ball=(centre[0], centre[1], radius)), 80)
    full = BallDetector().detect(decode_jpeg(jpeg))
    half_image = decode_jpeg(jpeg, 2)
    assert half_image.shape == (400, 400, 3)
    half = BallDetector().detect(half_image, scale=2)
    assert half is not None and full is not None
    # what the servo uses (centroid, radius) within 1.5 px (2 % of a large radius);
    # the enclosing circle of a ball cut by the edge within 3 px
    assert abs(half.cx - full.cx) <= 1.5 and abs(half.cy - full.cy) <= 1.5, (half, full)
    assert abs(half.radius - full.radius) <= max(1.5, 0.02 * full.radius), (half, full)
    assert abs(half.x - full.x) <= 3 and abs(half.y - full.y) <= 3, (half, full)


def test_the_800_px_threshold_holds_at_half_scale():
    """Radius 10 px at 800 px is the limit whatever the scale."""
    for radius, seen in ((8, False), (14, True)):
        jpeg = encode_jpeg(scene(800, 800, ball=(400, 200, radius)), 95)
        assert (BallDetector().detect(decode_jpeg(jpeg, 2), scale=2) is not None) == seen
        assert (BallDetector().detect(decode_jpeg(jpeg)) is not None) == seen


def test_vision_scale_keeps_400_px_of_width_and_empty_data_is_no_image():
    assert [vision_scale(w) for w in (320, 400, 799, 800, 1280, 1600, 3200)] == [
        1, 1, 1, 2, 2, 4, 8]
    assert decode_jpeg(b'') is None and decode_jpeg(b'not a jpeg') is None


@pytest.mark.parametrize('data', [b'', b'\x00', b'not a jpeg at all', bytes(range(256)) * 4,
                                  b'\xff\xd8\xff\xe0' + b'\x00' * 60])
def test_a_frame_that_is_not_a_jpeg_image_decodes_to_none(data):
    assert decode_jpeg(data) is None


def test_a_truncated_jpeg_is_not_an_image_or_is_a_whole_one():
    img = np.zeros((64, 64, 3), np.uint8)
    data = encode_jpeg(img, 80)
    decoded = decode_jpeg(data[:len(data) // 2])
    assert decoded is None or decoded.shape == (64, 64, 3)


def _chroma_sampling(jpeg):
    """(h, v) sampling factors of each component in a baseline JPEG's frame header."""
    at = jpeg.find(b'\xff\xc0')
    assert at >= 0, 'not a baseline JPEG'
    count = jpeg[at + 9]
    return [(jpeg[at + 11 + 3 * i] >> 4, jpeg[at + 11 + 3 * i] & 15) for i in range(count)]


@pytest.mark.parametrize('encoder', ['installed', 'opencv'])
def test_a_jpeg_is_what_opencv_makes_of_the_same_pixels(encoder, monkeypatch):
    """simplejpeg where installed, OpenCV else: baseline, 4:2:0 chroma, the same
    quality (their decoded pixels differ by a rounding), the input's colours."""
    from exp_assignment2 import vision
    if encoder == 'opencv':
        monkeypatch.setattr(vision, 'simplejpeg', None)
    img = scene(width=800, height=600, ball=(500, 300, 80))
    img[40:120, 40:200] = (30, 60, 220)
    jpeg = vision.encode_jpeg(img, 80)
    ok, reference = cv2.imencode('.jpg', img, [int(cv2.IMWRITE_JPEG_QUALITY), 80])
    assert ok and jpeg[:2] == b'\xff\xd8'
    assert _chroma_sampling(jpeg) == _chroma_sampling(reference.tobytes()) == \
        [(2, 2), (1, 1), (1, 1)]
    ours, theirs = decode_jpeg(jpeg).astype(int), decode_jpeg(reference.tobytes()).astype(int)
    assert np.abs(ours - theirs).mean() < 0.5 and np.abs(ours - img).mean() < 2.0
    assert 0.9 < len(jpeg) / len(reference) < 1.1


def test_a_jpeg_of_a_view_or_an_odd_quality_is_made_all_the_same():
    """Pixels that are a view (not contiguous) and qualities out of 1..100 (OpenCV
    clamps them) still make a JPEG."""
    img = scene(width=400, height=300, ball=(200, 150, 40))
    for pixels, quality in ((img[:, ::2], 80), (img, 0), (img, 150)):
        decoded = decode_jpeg(encode_jpeg(pixels, quality))
        assert decoded is not None and decoded.shape == pixels.shape

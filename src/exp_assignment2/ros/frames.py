"""Camera frames as a node receives them."""
import rospy

from exp_assignment2.grammar import quote
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.vision import decode_jpeg


class FrameDecoder(object):
    """JPEG ``CompressedImage`` messages of ``topic`` -> BGR images (at
    1/``scale`` of their size); a frame that is not one (empty, garbage) is
    dropped with a WARN naming the topic, at most one line every 10 s with the
    count of those held back."""

    def __init__(self, topic):
        self.warn = RefusalLog(topic, rospy.logwarn, period=10.0, what='dropped')

    def __call__(self, msg, scale=1):
        """The BGR image of ``msg``, or None."""
        bgr = decode_jpeg(msg.data, scale)
        if bgr is None:
            self.warn('a frame that is not a JPEG image (%d bytes, format %s) dropped'
                      % (len(msg.data), quote(msg.format)))
        return bgr

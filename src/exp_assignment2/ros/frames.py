"""Camera frames as a node receives them."""
import rospy

from exp_assignment2.vision import decode_jpeg


def decode_frame(msg, who, scale=1):
    """The BGR image of a JPEG ``CompressedImage`` (at 1/``scale`` of its
    size); None, with a warning naming ``who`` (at most one every 10 s), when
    it is not one."""
    bgr = decode_jpeg(msg.data, scale)
    if bgr is None:
        rospy.logwarn_throttle(10.0, '%s: a frame that is not a JPEG image' % who)
    return bgr

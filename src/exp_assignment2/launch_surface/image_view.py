"""rqt_image_view's stand-in (Debian has no rqt_image_view): the package's
image window on the topic it is given.

``rqt_image_view [TOPIC]``: a ``sensor_msgs/Image`` topic (``rgb8``, ``bgr8``,
``mono8``, ``rgba8``, ``bgra8``), or a ``.../compressed`` one
(``sensor_msgs/CompressedImage``, JPEG or PNG). With a display the frames
are shown in the package's camera window (:class:`exp_assignment2.ros.dog.
ImageWindow`); without one it says so in one line. Either way it never ends
on its own (a launch file may mark it required): it waits until stopped.
"""
import os

import numpy as np
import rospy
from sensor_msgs.msg import CompressedImage, Image

from exp_assignment2.launch_surface import viewer
from exp_assignment2.launch_surface.stopping import Stop

CHANNELS = {'rgb8': (3, True), 'bgr8': (3, False), 'mono8': (1, False), 'rgba8': (4, True),
            'bgra8': (4, False)}


def topic_of(argv):
    """The image topic among rqt_image_view's arguments (the first plain one), or ''."""
    for arg in argv:
        if not arg.startswith('-') and ':=' not in arg:
            return arg
    return ''


def to_bgr(msg):
    """A BGR array of an Image or CompressedImage; ValueError for an encoding it cannot show."""
    import cv2
    if isinstance(msg, CompressedImage):
        frame = cv2.imdecode(np.frombuffer(msg.data, np.uint8), cv2.IMREAD_COLOR)
        if frame is None:
            raise ValueError('a compressed image that does not decode (%s)' % msg.format)
        return frame
    if msg.encoding not in CHANNELS:
        raise ValueError('encoding %r; shown: %s' % (msg.encoding, ', '.join(sorted(CHANNELS))))
    channels, rgb = CHANNELS[msg.encoding]
    rows = np.frombuffer(msg.data, np.uint8).reshape(msg.height, msg.step)
    frame = rows[:, :msg.width * channels].reshape(msg.height, msg.width, channels)
    if channels == 1:
        return cv2.cvtColor(frame, cv2.COLOR_GRAY2BGR)
    frame = frame[:, :, :3]
    return np.ascontiguousarray(frame[:, :, ::-1] if rgb else frame)


def main():
    """The rqt_image_view executable."""
    stop = Stop()
    topic = topic_of(rospy.myargv()[1:])
    display = viewer.display_of(os.environ)
    # only a window that shows frames needs the simulated time (its hold timer): otherwise
    # no /clock, which comes a thousand times a simulated second (0.012 of a core)
    rospy.init_node('rqt_image_view', anonymous=True, disable_signals=True,
                    disable_rostime=display is None or not topic)
    try:
        if display is None:
            rospy.loginfo('rqt_image_view: no display (DISPLAY is not set), so no window for %s;'
                          ' the launch runs on', topic or 'any topic')
        elif not topic:
            rospy.loginfo('rqt_image_view: no topic given (rqt_image_view TOPIC), so nothing '
                          'to show; the launch runs on')
        else:
            _show(topic, display)
    except Exception as exc:        # a viewer never ends the launch
        rospy.logerr('rqt_image_view: cannot show %s: %s; the launch runs on', topic, exc)
    stop.wait()
    rospy.signal_shutdown('rqt_image_view stopped')
    return 0


def _show(topic, display):
    from exp_assignment2.ros.dog import ImageWindow
    window = ImageWindow('rqt_image_view %s' % topic)
    told = []

    def on_image(msg):
        try:
            window.show(to_bgr(msg))
        except ValueError as exc:
            if not told:
                told.append(exc)
                rospy.logwarn('rqt_image_view: %s: %s', topic, exc)

    cls = CompressedImage if topic.rstrip('/').endswith('/compressed') else Image
    rospy.Subscriber(topic, cls, on_image, queue_size=1, buff_size=2 ** 24)
    rospy.loginfo('rqt_image_view: showing %s on display %s', topic, display)

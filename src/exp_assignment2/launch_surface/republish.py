"""image_transport's ``republish``: one image stream in another transport.

    republish IN_TRANSPORT in:=BASE_TOPIC [OUT_TRANSPORT] out:=BASE_TOPIC

as in a launch file (``args="compressed in:=/robot/camera1/image_raw raw
out:=/robot/image"``). The transports are the two Debian lacks the plugins
for and this package's camera speaks: ``raw`` (sensor_msgs/Image on the base
topic) and ``compressed`` (sensor_msgs/CompressedImage, JPEG, on
``BASE/compressed``). Without OUT_TRANSPORT it publishes in both, as
image_transport publishes in every transport it has. Lazier than
image_transport (whose republish always subscribes to its input): the input
is subscribed to only while an output has a subscriber. Raw images go to JPEG from ``bgr8``, ``rgb8`` and ``mono8``
(quality ``~jpeg_quality``, 80); other encodings are dropped with a
throttled WARN naming them.
"""
import sys
import threading

import numpy as np
import rospy
from sensor_msgs.msg import CompressedImage, Image

from exp_assignment2.refusal import RefusalLog
from exp_assignment2.ros.frames import FrameDecoder

TRANSPORTS = {'raw': ('', Image), 'compressed': ('/compressed', CompressedImage)}
USAGE = 'usage: republish IN_TRANSPORT in:=<in base topic> [OUT_TRANSPORT] out:=<out base topic>'


def parse(argv):
    """(in transport, [out transports]) from the arguments left after remaps."""
    if not 1 <= len(argv) <= 2:
        raise ValueError(USAGE)
    for transport in argv:
        if transport not in TRANSPORTS:
            raise ValueError("transport '%s' is not available here (raw, compressed); %s"
                             % (transport, USAGE))
    return argv[0], argv[1:] or sorted(TRANSPORTS)


class Relay(rospy.SubscribeListener):
    """``in`` in one transport -> ``out`` in another, while ``out`` is watched."""

    def __init__(self, in_transport, out_transport, quality=80):
        rospy.SubscribeListener.__init__(self)
        self.lock, self.sub = threading.Lock(), None
        suffix, self.in_type = TRANSPORTS[in_transport]
        self.in_topic = rospy.resolve_name('in') + suffix
        suffix, out_type = TRANSPORTS[out_transport]
        self.quality = quality
        self.convert = {('compressed', 'raw'): self.decompress,
                        ('raw', 'compressed'): self.compress}.get(
                            (in_transport, out_transport), lambda msg: msg)
        self.decode = FrameDecoder(self.in_topic)
        self.refused = RefusalLog(self.in_topic, rospy.logwarn, period=10.0, what='dropped')
        self.pub = rospy.Publisher(rospy.resolve_name('out') + suffix, out_type, queue_size=1,
                                   subscriber_listener=self)

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        self._update()

    def peer_unsubscribe(self, topic_name, num_peers):
        self._update()

    def _update(self):
        with self.lock:
            wanted = self.pub.get_num_connections() > 0
            if wanted and self.sub is None:
                self.sub = rospy.Subscriber(self.in_topic, self.in_type, self._on_image,
                                            queue_size=1, buff_size=2 ** 24)
            elif not wanted and self.sub is not None:
                self.sub.unregister()
                self.sub = None

    def _on_image(self, msg):
        out = self.convert(msg)
        if out is not None:
            self.pub.publish(out)

    def decompress(self, msg):
        bgr = self.decode(msg)
        if bgr is None:
            return None
        h, w = bgr.shape[:2]
        return Image(header=msg.header, height=h, width=w, encoding='bgr8', is_bigendian=0,
                     step=3 * w, data=bgr.tobytes())

    def compress(self, msg):
        import cv2
        from exp_assignment2.vision import encode_jpeg
        channels = {'bgr8': 3, 'rgb8': 3, 'mono8': 1}.get(msg.encoding)
        if channels is None or msg.step < msg.width * channels or \
                len(msg.data) < msg.step * msg.height:
            self.refused('an image of encoding %s, %dx%d, step %d, %d bytes dropped: raw '
                         'images go to JPEG from bgr8, rgb8 and mono8'
                         % (msg.encoding, msg.width, msg.height, msg.step, len(msg.data)))
            return None
        rows = np.frombuffer(msg.data, np.uint8, msg.step * msg.height).reshape(
            msg.height, msg.step)
        pixels = rows[:, :msg.width * channels].reshape(msg.height, msg.width, channels)
        if msg.encoding == 'rgb8':
            pixels = cv2.cvtColor(pixels, cv2.COLOR_RGB2BGR)
        if channels == 1:
            pixels = pixels[:, :, 0]
        stored = 'mono8' if channels == 1 else 'bgr8'
        return CompressedImage(header=msg.header,
                               format='%s; jpeg compressed %s' % (msg.encoding, stored),
                               data=encode_jpeg(np.ascontiguousarray(pixels), self.quality))


def main(argv=None):
    argv = rospy.myargv(sys.argv)[1:] if argv is None else argv
    try:
        in_transport, out_transports = parse(argv)
    except ValueError as exc:
        print('republish: %s' % exc, file=sys.stderr)
        return 2
    rospy.init_node('image_republisher', anonymous=True)
    quality = int(rospy.get_param('~jpeg_quality', 80))
    relays = [Relay(in_transport, out, quality) for out in out_transports]   # noqa: F841
    rospy.spin()
    return 0

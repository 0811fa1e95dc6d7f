"""A JPEG CompressedImage stream as raw sensor_msgs/Image, for rviz's Image
display: Debian bookworm has no compressed_image_transport, so rviz can only
show raw images.

Lazy, as image_transport is: it subscribes to ``in`` only while ``out`` has a
subscriber, so a publisher that works only when watched stays idle.
"""
import threading

import rospy
from sensor_msgs.msg import CompressedImage, Image

from exp_assignment2.ros.frames import FrameDecoder


class Decompressor(rospy.SubscribeListener):
    """``in`` (CompressedImage, JPEG) -> ``out`` (Image, bgr8)."""

    def __init__(self):
        rospy.SubscribeListener.__init__(self)
        self.lock, self.sub = threading.Lock(), None
        self.decode = FrameDecoder(rospy.resolve_name('in'))
        self.pub = rospy.Publisher('out', Image, queue_size=1, subscriber_listener=self)

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        self._update()

    def peer_unsubscribe(self, topic_name, num_peers):
        self._update()

    def _update(self):
        with self.lock:
            wanted = self.pub.get_num_connections() > 0
            if wanted and self.sub is None:
                self.sub = rospy.Subscriber('in', CompressedImage, self._on_image, queue_size=1,
                                            buff_size=2 ** 24)
            elif not wanted and self.sub is not None:
                self.sub.unregister()
                self.sub = None

    def _on_image(self, msg):
        bgr = self.decode(msg)
        if bgr is None:
            return
        h, w = bgr.shape[:2]
        self.pub.publish(Image(header=msg.header, height=h, width=w, encoding='bgr8',
                               is_bigendian=0, step=3 * w, data=bgr.tobytes()))

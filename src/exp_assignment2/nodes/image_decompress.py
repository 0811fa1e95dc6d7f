"""``image_decompress``: ``in`` (a JPEG CompressedImage topic) -> ``out``
(sensor_msgs/Image), while someone subscribes; rviz.launch remaps them."""
import rospy

from exp_assignment2.ros.ending import run_until_shutdown
from exp_assignment2.ros.image_relay import Decompressor


def main():
    rospy.init_node('image_decompress')
    Decompressor()
    run_until_shutdown(rospy.spin)

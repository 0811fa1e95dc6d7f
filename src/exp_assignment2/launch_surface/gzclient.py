"""gazebo_ros' ``gzclient``: the viewer, or one line when there is no display.

With a display, rviz opens with the package's config (:mod:`.viewer`), and
this node broadcasts the models' and links' poses from ``/gazebo/model_states``
and ``/gazebo/link_states`` as TF frames for it, at most 20 times a second,
and draws each robot spawned from a URDF on the parameter server from that
URDF, its links moving with their frames (:mod:`.robot_drawing`, on
``/gazebo_gui/robot_markers``); closing the window ends the node, as closing
Gazebo's client does. Without a
display it says so in one line and waits until it is stopped (SIGINT or
SIGTERM, :mod:`.stopping`), so a launch file's ``gui:=true`` works headless.
On a display nobody watches live (``EXP2_VIEWER_FRAME_RATE`` set: the
grader's) there is no rviz: Gazebo's window shows the world as the simulator
draws it from Gazebo's user camera (:mod:`.gui_window`).
"""
import os
import subprocess
import threading
import time

import rospy
import tf2_ros
from gazebo_msgs.msg import LinkStates, ModelStates
from geometry_msgs.msg import TransformStamped
from visualization_msgs.msg import MarkerArray

from exp_assignment2.launch_surface import gui_window, robot_drawing, viewer
from exp_assignment2.launch_surface.stopping import Stop

CONFIG = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..',
                                       'original_env', 'stand_in_packages', 'gazebo_ros',
                                       'rviz', 'gzclient.rviz'))
PERIOD = 0.05       # wall s between two broadcasts of the same topic's frames
LOOK = 2.0          # wall s between two looks for descriptions of models not drawn yet
MARKERS = '/gazebo_gui/robot_markers'


class FrameBroadcaster(object):
    """Model and link states -> TF frames under ``world``, rate-limited."""

    def __init__(self, period=PERIOD):
        self.period = period
        self.tf = tf2_ros.TransformBroadcaster()
        self.last = {}
        rospy.Subscriber('/gazebo/model_states', ModelStates, self.on_states, 'models',
                         queue_size=1)
        rospy.Subscriber('/gazebo/link_states', LinkStates, self.on_states, 'links',
                         queue_size=1)

    def on_states(self, msg, which):
        now = time.monotonic()
        if now - self.last.get(which, 0.0) < self.period:
            return
        self.last[which] = now
        stamp = rospy.Time.now()
        out = []
        for frame, pose in viewer.frames(msg.name, msg.pose):
            t = TransformStamped()
            t.header.stamp, t.header.frame_id, t.child_frame_id = stamp, viewer.WORLD_FRAME, frame
            t.transform.translation.x = pose.position.x
            t.transform.translation.y = pose.position.y
            t.transform.translation.z = pose.position.z
            t.transform.rotation = pose.orientation
            out.append(t)
        if out:
            self.tf.sendTransform(out)


class RobotDrawer(object):
    """Draws the models that have a URDF on the parameter server (robot_drawing)."""

    def __init__(self):
        self.pub = rospy.Publisher(MARKERS, MarkerArray, queue_size=1, latch=True)
        self.drawn, self.undrawn, self.last_look = {}, set(), 0.0
        rospy.Subscriber('/gazebo/link_states', LinkStates, self.on_links, queue_size=1)

    def on_links(self, msg):
        links = {}
        for name in msg.name:
            model, _, link = name.partition('::')
            links.setdefault(model, set()).add(link)
        gone = set(self.drawn) - set(links)
        new = set(links) - set(self.drawn) - self.undrawn
        if not gone and not new and not (self.undrawn and
                                          time.monotonic() - self.last_look > LOOK):
            return
        self.undrawn = (self.undrawn | new) & set(links)
        for model in gone:
            del self.drawn[model]
        if self.undrawn:
            self.last_look = time.monotonic()
            descriptions = robot_drawing.find_descriptions(rospy.get_param_names(),
                                                           rospy.get_param)
            for model in sorted(self.undrawn):
                found = robot_drawing.match(links[model], descriptions)
                if found is not None:
                    self.drawn[model] = found
                    self.undrawn.discard(model)
                    rospy.loginfo('gzclient: drawing %s from %s (%d links)', model, found[0],
                                  len(found[1].links))
        markers = [robot_drawing.delete_all()]
        for model in sorted(self.drawn):
            markers += robot_drawing.robot_markers(model, self.drawn[model][1], len(markers))
        self.pub.publish(MarkerArray(markers=markers))


def main():
    """The gzclient executable (Gazebo's client options are accepted and unused)."""
    stop = Stop()
    display = viewer.display_of(os.environ)
    with_rviz = display is not None and viewer.frame_rate(os.environ) is None
    # only rviz's frames need the simulated time: otherwise no /clock, which comes
    # a thousand times a simulated second (Gazebo's client is no rospy node to pay for it)
    rospy.init_node('gazebo_gui', disable_signals=True, disable_rostime=not with_rviz)
    if display is None:
        rospy.loginfo('gzclient: no display (DISPLAY is not set), so no viewer window; the '
                      'simulation runs on. Set DISPLAY (or run under xvfb-run) to see it in rviz')
        stop.wait()
        rospy.signal_shutdown('gzclient stopped')
        return 0
    if not with_rviz:        # a display nobody watches live: Gazebo's window without rviz
        gui_window.show(stop)
        rospy.signal_shutdown('gzclient stopped')
        return 0
    FrameBroadcaster(PERIOD)
    RobotDrawer()
    name = rospy.get_name().rsplit('/', 1)[-1] + '_rviz'
    config = CONFIG
    rviz = subprocess.Popen(['rviz', '-d', config, '__name:=' + name])
    rospy.loginfo('gzclient: rviz on display %s (%s)', display, config)
    closed = threading.Event()
    threading.Thread(target=lambda: (rviz.wait(), closed.set()), daemon=True).start()
    if stop.wait(closed):       # the window was closed, or rviz could not start
        rospy.loginfo('gzclient: rviz ended (exit status %d)', rviz.returncode)
    rviz.terminate()
    try:
        rviz.wait(timeout=5)
    except subprocess.TimeoutExpired:
        rviz.kill()
    rospy.signal_shutdown('gzclient stopped')
    return 0

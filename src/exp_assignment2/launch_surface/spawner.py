"""controller_manager's ``spawner``: start a robot's controllers in the running
simulator, and take them down when it is stopped.

The controllers are the ones the parameter server describes under the
controller manager's namespace (``<ns>/<name>/type``, ``joint``, ``pid``),
as loaded from the user's YAML (or from a YAML file named in place of a
controller, whose top-level keys it loads, as the real spawner). It waits for ``<ns>/controller_manager``'s
services (``--timeout``), loads each controller, starts the loaded ones with
one strict switch (unless ``--stopped``), and stays up; stopped by roslaunch
(SIGINT or SIGTERM, :mod:`.stopping`: also while it is still starting them)
it stops and unloads them within ``--shutdown-timeout``.
"""
import os
import sys
import threading

import yaml

import rospy
from controller_manager_msgs.srv import LoadController, SwitchController, UnloadController
from std_msgs.msg import Bool

from exp_assignment2.launch_surface import spawner_args
from exp_assignment2.launch_surface.stopping import Stop

STRICT = 2      # SwitchController.STRICT


class Spawner(object):
    """The controllers of one spawner run: load, start, stop and unload."""

    def __init__(self, options, stop):
        self.options, self.stop = options, stop
        self.namespace = spawner_args.manager_namespace(options.namespace,
                                                        rospy.get_namespace())
        load, switch, unload = spawner_args.service_names(self.namespace)
        self.load = rospy.ServiceProxy(load, LoadController)
        self.switch = rospy.ServiceProxy(switch, SwitchController)
        self.unload = rospy.ServiceProxy(unload, UnloadController)
        self.loaded, self.started = [], False

    def wait_for_topic(self):
        """--wait-for TOPIC: until True is published there (at most --timeout s)."""
        heard = threading.Event()
        topic = self.options.wait_for
        sub = rospy.Subscriber(topic, Bool, lambda msg: msg.data and heard.set())
        rospy.loginfo('Controller Spawner: Waiting for %s to be True', topic)
        got = self.stop.wait(heard, self.options.timeout)
        sub.unregister()
        if not got and not self.stop:
            rospy.logerr('Controller Spawner: nothing True on %s within %g s', topic,
                         self.options.timeout)
        return got

    def wait_for_services(self):
        for proxy in (self.load, self.switch, self.unload):
            rospy.loginfo('Controller Spawner: Waiting for service %s', proxy.resolved_name)
            if not self.stop.wait_for_service(proxy.resolved_name, self.options.timeout):
                if self.stop:
                    return False
                rospy.logerr("Controller Spawner couldn't find the expected controller_manager "
                             'ROS interface (%s) within %g s: did spawn_model spawn a model whose '
                             'URDF has the ros_control plugin (libgazebo_ros_control.so), in '
                             'namespace %s?', proxy.resolved_name, self.options.timeout,
                             self.namespace)
                return False
        return True

    def start(self):
        """Load and start; False when nothing could be loaded or started."""
        if self.options.wait_for and not self.wait_for_topic():
            return False
        if not self.wait_for_services():
            return False
        for name in controller_names(self.options.controllers):
            rospy.loginfo('Loading controller: %s', name)
            try:
                ok = self.load(name).ok
            except (rospy.ServiceException, rospy.ROSException) as exc:
                rospy.logerr('Failed to load %s: %s', name, exc)
                continue
            if ok:
                self.loaded.append(name)
            else:
                param = self.namespace.rstrip('/') + '/' + name + '/type'
                hint = '' if rospy.has_param(param) else (
                    ': the parameter %s is not set (load the controllers\' YAML into %s with '
                    '<rosparam command="load" ns="%s">)' % (param, self.namespace, self.namespace))
                rospy.logerr('Failed to load %s%s', name, hint)
        rospy.loginfo('Controller Spawner: Loaded controllers: %s', ', '.join(self.loaded))
        if self.options.stopped or not self.loaded:
            return bool(self.loaded)
        try:
            self.started = self.switch(self.loaded, [], STRICT, False, 0.0).ok
        except (rospy.ServiceException, rospy.ROSException) as exc:
            rospy.logerr('Failed to start controllers %s: %s', ', '.join(self.loaded), exc)
            return False
        if self.started:
            rospy.loginfo('Started controllers: %s', ', '.join(self.loaded))
        else:
            rospy.logerr('Failed to start controllers: %s', ', '.join(self.loaded))
        return self.started

    def take_down(self):
        """Stop and unload what was loaded, within --shutdown-timeout s (a
        service call has no timeout of its own: a worker makes it)."""
        if not self.loaded:
            return
        worker = threading.Thread(target=self._take_down, daemon=True)
        worker.start()
        worker.join(self.options.shutdown_timeout)
        if worker.is_alive():
            rospy.logwarn('Controller Spawner: controllers not unloaded within %g s '
                          '(--shutdown-timeout)', self.options.shutdown_timeout)

    def _take_down(self):
        rospy.loginfo('Shutting down spawner. Stopping and unloading controllers...')
        try:
            rospy.wait_for_service(self.unload.resolved_name, timeout=0.5)
        except rospy.ROSException:
            # roslaunch stops every node at once: the simulator may be gone first
            rospy.loginfo('Controller Spawner: the controller manager has stopped already')
            return
        try:
            if self.started:
                self.switch([], self.loaded, STRICT, False, 0.0)
            for name in reversed(self.loaded):
                self.unload(name)
        except (rospy.ServiceException, rospy.ROSException) as exc:
            rospy.logwarn('Controller Spawner error while taking down controllers: %s', exc)


def controller_names(names):
    """The controllers to load: a name that is a YAML file is loaded into the
    node's namespace and stands for its top-level keys, as the real spawner
    (``rosparam.set_param("", open(name))``) reads it."""
    out = []
    for name in names:
        if not os.path.isfile(name):
            out.append(name)
            continue
        with open(name) as f:
            data = yaml.safe_load(f) or {}
        for key, value in data.items():
            rospy.set_param(key, value)
            out.append(key)
    return out


def main(argv=None):
    """The spawner executable: 0 after a clean stop, 1 when it could not start
    the controllers, 2 for a command line it refuses."""
    argv = rospy.myargv(sys.argv if argv is None else argv)[1:]
    if '-h' in argv or '--help' in argv:
        print(spawner_args.USAGE)
        return 0
    try:
        options = spawner_args.parse(argv)
    except spawner_args.UsageError as exc:
        print(str(exc), file=sys.stderr)
        return 2
    stop = Stop()
    # no /clock (a thousand a simulated second): nothing here is timed in simulated time
    rospy.init_node('spawner', anonymous=True, disable_signals=True, disable_rostime=True)
    spawner = Spawner(options, stop)
    started = spawner.start()
    if started:
        stop.wait()
    spawner.take_down()
    rospy.signal_shutdown('spawner stopped')
    return 0 if started or stop else 1

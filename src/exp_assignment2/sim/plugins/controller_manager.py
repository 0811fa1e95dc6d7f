"""gazebo_ros_control's controller manager for one robot namespace: the
controllers its YAML declares (:mod:`.controllers`), and the services
``<ns>/controller_manager/*`` that load, switch, list and unload them."""
import copy

import rospy
from controller_manager_msgs.msg import ControllerState, HardwareInterfaceResources
from controller_manager_msgs.srv import (ListControllers, ListControllersResponse,
                                         LoadController, LoadControllerResponse,
                                         SwitchController, SwitchControllerResponse,
                                         UnloadController, UnloadControllerResponse)

from exp_assignment2.sim.plugins.controllers import CONTROLLER_TYPES, incomplete


class ControllerManager(object):
    """Runs the declared controllers of one robot namespace and serves
    ``<ns>/controller_manager/*`` (see :mod:`.ros_control`)."""

    def __init__(self, plugin, ns):
        self.plugin, self.ns = plugin, ns
        self.running, self.stopped, self.declared = {}, {}, {}
        self.unloaded, self.warned = set(), set()
        self.publishers = {}
        call = plugin.engine.call_and_wait
        base = ns + '/controller_manager/'
        self.services = [
            rospy.Service(base + 'load_controller', LoadController,
                          lambda req: LoadControllerResponse(call(lambda: self.load(req.name)))),
            rospy.Service(base + 'unload_controller', UnloadController,
                          lambda req: UnloadControllerResponse(
                              call(lambda: self.unload(req.name)))),
            rospy.Service(base + 'switch_controller', SwitchController,
                          lambda req: SwitchControllerResponse(call(
                              lambda: self.switch(req.start_controllers, req.stop_controllers,
                                                  req.strictness)))),
            rospy.Service(base + 'list_controllers', ListControllers,
                          lambda req: ListControllersResponse(call(self.list))),
        ]

    def publisher(self, topic, cls):
        """The namespace's one publisher of ``topic``, shared by the controllers
        that use it (:meth:`release` when done) and kept while one replaces
        another: a joint_state_controller replaced by a user's YAML (its own
        publish_rate) that unregistered its publisher and made a new one left
        subscribers (robot_state_publisher too) with no connection now and
        then, when the master's two updates crossed."""
        entry = self.publishers.get(topic)
        if entry is None:
            entry = self.publishers[topic] = [rospy.Publisher(topic, cls, queue_size=10), 0]
        entry[1] += 1
        return entry[0]

    def release(self, topic):
        """A controller is done with ``topic``: the last one unregisters it
        (an unloaded joint_state_controller takes its topic away, as Gazebo's)."""
        entry = self.publishers.get(topic)
        if entry is not None:
            entry[1] -= 1
            if entry[1] <= 0:
                del self.publishers[topic]
                entry[0].unregister()

    def _warn_once(self, name, text):
        if (name, text) not in self.warned:
            self.warned.add((name, text))
            rospy.logwarn('%s: controller %s: %s; ignored'
                          % (self.plugin.model.name, name, text))

    def _make(self, name, config):
        kind = config.get('type')
        cls = CONTROLLER_TYPES.get(kind)
        if cls is None:
            self._warn_once(name, 'type %r is not simulated here (known: %s)'
                            % (kind, ', '.join(sorted(CONTROLLER_TYPES))))
            return None
        try:
            return cls(self, name, config)
        except ValueError as exc:
            self._warn_once(name, str(exc))
            return None

    def discover(self, params, patient=True):
        """Start what ``params`` (the namespace's parameters) declares anew.
        ``patient``: a joint controller with no ``joint`` yet is left for
        later, neither started nor warned about (a YAML still arriving);
        returns the names of those."""
        # copies: the parameters may be rospy's cache, which updates in place
        declared = {n: copy.deepcopy(c) for n, c in params.items()
                    if isinstance(c, dict) and 'type' in c}
        waiting = []
        for name, config in declared.items():
            if self.declared.get(name) == config and (name in self.running or
                                                      name in self.stopped):
                continue
            if patient and incomplete(config):
                waiting.append(name)
                continue
            self.declared[name] = config
            if name in self.unloaded:
                continue
            controller = self._make(name, config)      # before the old one goes: the
            self._drop(name)                           # topics it shares stay up
            if controller is not None:
                self.running[name] = controller
        return waiting

    def _drop(self, name):
        controller = self.running.pop(name, None) or self.stopped.pop(name, None)
        if controller is not None:
            controller.stop()

    def load(self, name):
        """controller_manager/load_controller: True once it exists (started)."""
        if name in self.running or name in self.stopped:
            return True
        config = rospy.get_param('%s/%s' % (self.ns, name), None)
        if not isinstance(config, dict) or 'type' not in config:
            rospy.logerr('%s/controller_manager: no controller %s/%s/type on the parameter '
                         'server' % (self.ns, self.ns, name))
            return False
        self.unloaded.discard(name)
        self.declared[name] = config
        controller = self._make(name, config)
        if controller is not None:
            self.running[name] = controller
        return controller is not None

    def unload(self, name):
        """controller_manager/unload_controller: stop it and forget it."""
        if name not in self.running and name not in self.stopped:
            return False
        self._drop(name)
        self.unloaded.add(name)
        return True

    def switch(self, start, stop, strictness):
        """controller_manager/switch_controller (STRICT: all or nothing)."""
        unknown = [n for n in list(start) + list(stop)
                   if n not in self.running and n not in self.stopped]
        if unknown and strictness == SwitchController._request_class.STRICT:
            rospy.logerr('%s/controller_manager: cannot switch %s: not loaded'
                         % (self.ns, ', '.join(unknown)))
            return False
        for name in stop:
            if name in self.running:
                self.stopped[name] = self.running.pop(name)
        for name in start:
            if name in self.stopped:
                self.running[name] = self.stopped.pop(name)
        return True

    def list(self):
        return [ControllerState(name=name, state=state, type=self.declared[name]['type'],
                                claimed_resources=[HardwareInterfaceResources(
                                    hardware_interface=c.hardware, resources=c.joints)])
                for group, state in ((self.running, 'running'), (self.stopped, 'stopped'))
                for name, c in sorted(group.items())]

    def apply(self):
        for controller in self.running.values():
            controller.apply()

    def publish(self):
        for controller in self.running.values():
            controller.publish()

    def reset(self):
        for controller in list(self.running.values()) + list(self.stopped.values()):
            controller.reset()

    def close(self):
        for name in list(self.running) + list(self.stopped):
            self._drop(name)
        for service in self.services:
            service.shutdown()
        for pub, _ in self.publishers.values():     # none should be left
            pub.unregister()
        self.publishers.clear()

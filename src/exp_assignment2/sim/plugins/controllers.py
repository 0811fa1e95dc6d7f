"""The controllers gazebo_ros_control runs, and their manager's services
(see :mod:`.ros_control`)."""
import copy

import rospy
from controller_manager_msgs.msg import ControllerState, HardwareInterfaceResources
from controller_manager_msgs.srv import (ListControllers, ListControllersResponse,
                                         LoadController, LoadControllerResponse,
                                         SwitchController, SwitchControllerResponse,
                                         UnloadController, UnloadControllerResponse)
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64

from exp_assignment2.grammar import show_number
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.sim.drives import JointPosition
from exp_assignment2.sim.plugins.cores import Every
from exp_assignment2.sim.plugins.ros_io import publish_joint_states

HEAD_SPEED, HEAD_EFFORT = 2.0, 5.0     # rad/s and N m a position controller uses at most


class JointStateController(object):
    """``<ns>/joint_states`` of every movable joint at ``publish_rate`` Hz."""

    hardware = 'hardware_interface/JointStateInterface'

    def __init__(self, manager, name, config):
        self.model, self.engine = manager.plugin.model, manager.plugin.engine
        self.joints = []
        rate = config.get('publish_rate', 50.0)
        if isinstance(rate, bool) or not isinstance(rate, (int, float)) or not rate > 0:
            raise ValueError('%s/publish_rate must be a positive number, got %r'
                             % (name, rate))
        self.every = Every(float(rate), lambda: self.engine.time)
        self.manager, self.topic = manager, manager.ns + '/joint_states'
        self.pub = manager.publisher(self.topic, JointState)

    def apply(self):
        pass

    def publish(self):
        if self.every.due():
            publish_joint_states(self.pub, self.model, self.engine)

    def reset(self):
        self.every.reset()

    def stop(self):
        self.manager.release(self.topic)    # a replacement made first goes on with it


class JointCommandController(object):
    """A Float64 ``<ns>/<name>/command`` for one joint (``joint`` in the YAML);
    non-finite commands are ignored, others clamped to the joint's limits,
    each with a warning at most every 5 s."""

    def __init__(self, manager, name, config):
        self.model, self.engine = manager.plugin.model, manager.plugin.engine
        joint = config.get('joint')
        if joint is None:
            raise ValueError('no joint given (%s/%s/joint is not set)' % (manager.ns, name))
        if not isinstance(joint, str) or not self.model.has_joint(joint):
            raise ValueError('%s: joint %r is not a joint of model %s (it has: %s)'
                             % (name, joint, self.model.name,
                                ', '.join(self.model.movable_joints) or 'none'))
        self.joints = [joint]
        # position_controllers/... drives a PositionJointInterface, and so on
        self.hardware = 'hardware_interface/%sJointInterface' % (
            config['type'].split('_')[0].capitalize())
        self.topic = '%s/%s/command' % (manager.ns, name)
        self.ignored = RefusalLog(self.topic, rospy.logwarn, period=5.0, what='ignored')
        self.clamped = RefusalLog(self.topic, rospy.logwarn, period=5.0, what='clamped')
        self.sub = rospy.Subscriber(self.topic, Float64, self._on_command, queue_size=1)

    def _on_command(self, msg):
        value = msg.data
        self.engine.call_soon(lambda: self._take(value))

    def _take(self, value):
        try:
            used = self.command(value)
        except ValueError as exc:
            self.ignored('ignored: %s' % exc)
            return
        if used != value:
            self.clamped('%s clamped to %s' % (show_number(value), show_number(used)))

    def publish(self):
        pass

    def stop(self):
        self.sub.unregister()


class PositionController(JointCommandController):
    """A JointPositionController: the command is the joint's target."""

    def __init__(self, manager, name, config):
        JointCommandController.__init__(self, manager, name, config)
        self.drive = JointPosition(self.model, self.joints[0], HEAD_SPEED, HEAD_EFFORT)
        self.command = self.drive.command

    def apply(self):
        self.drive.apply()

    def reset(self):
        self.drive.reset()


class VelocityController(JointCommandController):
    """A JointVelocityController: the command is the joint's velocity (rad/s)."""

    def __init__(self, manager, name, config):
        JointCommandController.__init__(self, manager, name, config)
        joint = self.model.urdf.joints[self.joints[0]]
        self.limit, self.effort = min(joint.velocity, 100.0), min(joint.effort, 100.0)
        self.velocity = 0.0

    def command(self, value):
        if not value == value or value in (float('inf'), float('-inf')):
            raise ValueError('joint velocity command %s is not finite' % show_number(value))
        self.velocity = max(-self.limit, min(self.limit, float(value)))
        return self.velocity

    def apply(self):
        self.model.set_joint_velocity(self.joints[0], self.velocity, self.effort)

    def reset(self):
        self.velocity = 0.0


CONTROLLER_TYPES = {
    'joint_state_controller/JointStateController': JointStateController,
    'position_controllers/JointPositionController': PositionController,
    'effort_controllers/JointPositionController': PositionController,
    'velocity_controllers/JointPositionController': PositionController,
    'velocity_controllers/JointVelocityController': VelocityController,
    'effort_controllers/JointVelocityController': VelocityController,
}


def incomplete(config):
    """A joint controller's parameters without its ``joint`` (yet)."""
    cls = CONTROLLER_TYPES.get(config.get('type'))
    return (cls is not None and issubclass(cls, JointCommandController)
            and 'joint' not in config)


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

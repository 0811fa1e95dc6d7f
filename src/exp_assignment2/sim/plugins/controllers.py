"""The controllers gazebo_ros_control runs (see :mod:`.ros_control`; their
manager and its services: :mod:`.controller_manager`)."""
import math

import rospy
from control_msgs.msg import JointControllerState
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64

from exp_assignment2.grammar import show_number
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.sim.drives import JointPosition
from exp_assignment2.sim.plugins.cores import Every
from exp_assignment2.sim.plugins.ros_io import joint_claims, publish_joint_states, stamp, \
    subscribe

HEAD_SPEED, HEAD_EFFORT = 2.0, 5.0     # rad/s and N m a position controller uses at most
# the controllers ros_controllers runs through a PID, which publish <ns>/<name>/state
# (the forwarding ones, position_controllers/JointPositionController and
# velocity_controllers/JointVelocityController, publish none)
PID_TYPES = ('effort_controllers/JointPositionController',
             'velocity_controllers/JointPositionController',
             'effort_controllers/JointVelocityController')


class JointStateController(object):
    """``<ns>/joint_states`` of every movable joint at ``publish_rate`` Hz,
    but those another plugin publishes there (:func:`~.ros_io.joint_claims`:
    the diff drive's wheels with publishWheelJointState)."""

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
            claimed = set().union(*joint_claims(self.engine, self.topic).values())
            names = [j for j in self.model.movable_joints if j not in claimed]
            if names:
                publish_joint_states(self.pub, self.model, self.engine, names)

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
        self.sub = subscribe(self.topic, Float64, self._on_command, queue_size=1)
        self.state = None
        if config['type'] in PID_TYPES:
            self.state = StateTopic(manager, name, config, self.joints[0])

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

    def set_point(self):
        """What the controller drives the joint to (its position or velocity)."""
        raise NotImplementedError

    def publish(self):
        if self.state is not None:
            self.state.publish(self.set_point(), self.controls_velocity)

    def stop(self):
        self.sub.unregister()
        if self.state is not None:
            self.state.stop()


class StateTopic(object):
    """``<ns>/<name>/state`` (control_msgs/JointControllerState) of a PID
    controller, every update: set point, the joint's position or velocity
    (``process_value``) and the error between them, the torque the joint's
    motor applied (``command``), and the gains of the YAML's ``pid``."""

    def __init__(self, manager, name, config, joint):
        self.manager, self.engine = manager, manager.plugin.engine
        self.model, self.joint = manager.plugin.model, joint
        self.continuous = self.model.urdf.joints[joint].type == 'continuous'
        pid = config.get('pid') if isinstance(config.get('pid'), dict) else {}
        self.gains = [_gain(pid, key) for key in ('p', 'i', 'd')] + [
            _gain(pid, 'i_clamp', _gain(pid, 'i_clamp_max'))]
        self.antiwindup = bool(pid.get('antiwindup', False))
        self.topic = '%s/%s/state' % (manager.ns, name)
        self.pub = manager.publisher(self.topic, JointControllerState)

    def publish(self, set_point, of_velocity):
        _, [position], [velocity], [effort] = self.model.joint_states([self.joint])
        value = velocity if of_velocity else position
        error = set_point - value
        if self.continuous and not of_velocity:
            error = math.atan2(math.sin(error), math.cos(error))
        msg = JointControllerState(set_point=set_point, process_value=value,
                                   process_value_dot=0.0 if of_velocity else velocity,
                                   error=error, time_step=self.engine.time_step, command=effort,
                                   antiwindup=self.antiwindup)
        msg.p, msg.i, msg.d, msg.i_clamp = self.gains
        msg.header.stamp = stamp(self.engine)
        self.pub.publish(msg)

    def stop(self):
        self.manager.release(self.topic)


def _gain(pid, key, default=0.0):
    value = pid.get(key, default)
    return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) \
        else default


class PositionController(JointCommandController):
    """A JointPositionController: the command is the joint's target."""

    controls_velocity = False

    def __init__(self, manager, name, config):
        JointCommandController.__init__(self, manager, name, config)
        self.drive = JointPosition(self.model, self.joints[0], HEAD_SPEED, HEAD_EFFORT)
        self.command = self.drive.command

    def set_point(self):
        return self.drive.target

    def apply(self):
        self.drive.apply()

    def reset(self):
        self.drive.reset()


class VelocityController(JointCommandController):
    """A JointVelocityController: the command is the joint's velocity (rad/s)."""

    controls_velocity = True

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

    def set_point(self):
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

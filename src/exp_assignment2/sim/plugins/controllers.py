"""The controllers gazebo_ros_control runs (see :mod:`.ros_control`; their
manager and its services: :mod:`.controller_manager`)."""
import rospy
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64

from exp_assignment2.grammar import show_number
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.sim.drives import JointPosition
from exp_assignment2.sim.plugins.cores import Every
from exp_assignment2.sim.plugins.ros_io import joint_claims, publish_joint_states

HEAD_SPEED, HEAD_EFFORT = 2.0, 5.0     # rad/s and N m a position controller uses at most


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

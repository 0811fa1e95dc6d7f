"""Joint commands and joint states: the head's position controller, the
ball's height, and ``joint_states`` (what gazebo_ros_control published)."""
import rospy
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64, Header

from exp_assignment2.grammar import show_number
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.sim.drives import Height, JointPosition


class CommandPlugin(object):
    """A Float64 command topic for a controller that takes one number."""

    def __init__(self, sim, model, options, controller):
        self.sim, self.controller = sim, controller
        self.topic = model.topic(options['topic'])
        self.ignored = RefusalLog(self.topic, rospy.logwarn, period=5.0, what='ignored')
        self.clamped = RefusalLog(self.topic, rospy.logwarn, period=5.0, what='clamped')
        sim.drives[model.name + '/' + options['topic']] = controller
        rospy.Subscriber(self.topic, Float64, self._on_command, queue_size=1)

    def _on_command(self, msg):
        value = msg.data
        self.sim.run_in_loop(lambda: self._command(value))

    def _command(self, value):
        try:
            used = self.controller.command(value)
        except ValueError as exc:
            self.ignored('ignored: %s' % exc)
            return
        if used != value:
            self.clamped('%s clamped to %s' % (show_number(value), show_number(used)))

    def before_step(self):
        self.controller.apply()

    def reset(self):
        self.controller.reset()


class JointPositionPlugin(CommandPlugin):
    """``<ns>/joint_position_controller/command``: a joint's angle (rad)."""

    def __init__(self, sim, model, options):
        CommandPlugin.__init__(self, sim, model, options,
                               JointPosition(sim.physics, model.name, options))


class HeightPlugin(CommandPlugin):
    """``<ns>/height_controller/command``: a kinematic body's height (m); below
    0 it is under the ground, out of every camera's view."""

    def __init__(self, sim, model, options):
        CommandPlugin.__init__(self, sim, model, options,
                               Height(sim.physics, model.name, options))


class JointStatePlugin(object):
    """``<ns>/joint_states`` of every movable joint, at ``rate`` Hz of simulated time."""

    def __init__(self, sim, model, options):
        self.sim, self.name = sim, model.name
        self.period, self.next = 1.0 / options['rate'], 0.0
        self.pub = rospy.Publisher(model.topic(options['topic']), JointState, queue_size=10)

    def after_step(self, stamp):
        if self.sim.physics.time + 1e-9 < self.next:
            return
        self.next += self.period
        names, positions, velocities, efforts = self.sim.physics.joint_states(self.name)
        self.pub.publish(JointState(header=Header(stamp=stamp), name=names, position=positions,
                                    velocity=velocities, effort=efforts))

    def reset(self):
        self.next = self.sim.physics.time

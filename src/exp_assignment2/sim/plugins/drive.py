"""``cmd_vel`` for a body: Gazebo's diff_drive and planar_move plugins."""
import rospy
from geometry_msgs.msg import Twist

from exp_assignment2.grammar import show_numbers
from exp_assignment2.refusal import RefusalLog
from exp_assignment2.sim.drives import DiffDrive, PlanarMove


class DrivePlugin(object):
    """Subscribes ``<ns>/cmd_vel``; non-finite commands are ignored, commands
    beyond the limits clamped, each with a throttled warning."""

    def __init__(self, sim, model, drive):
        self.sim, self.model, self.drive = sim, model, drive
        sim.drives[model.name] = drive
        self.topic = model.topic(drive.options['topic'])
        # one warning line per topic and 5 s, whatever arrives (throttled by topic)
        self.ignored = RefusalLog(self.topic, rospy.logwarn, period=5.0, what='ignored')
        self.clamped = RefusalLog(self.topic, rospy.logwarn, period=5.0, what='clamped')
        rospy.Subscriber(self.topic, Twist, self._on_twist, queue_size=1)

    def _on_twist(self, msg):
        values = (msg.linear.x, msg.linear.y, msg.angular.z)
        self.sim.run_in_loop(lambda: self._command(values))

    def _command(self, values):
        try:
            clamped = self.drive.command(*values)
        except ValueError as exc:
            self.ignored('ignored: %s' % exc)
            return
        if clamped:
            self.clamped('%s clamped to the limits, %s'
                         % (show_numbers(values), self.drive.limits))

    def before_step(self):
        self.drive.apply()

    def reset(self):
        self.drive.reset()


class DiffDrivePlugin(DrivePlugin):
    """Two wheels. Sets ``<ns>/turn_sign`` (+1: +angular.z turns left, REP 103;
    -1: the original robot's wiring) for nodes that must know."""

    def __init__(self, sim, model, options):
        DrivePlugin.__init__(self, sim, model, DiffDrive(sim.physics, model.name, options))
        rospy.set_param(model.topic('turn_sign'), self.drive.turn_sign)


class PlanarMovePlugin(DrivePlugin):
    """Omnidirectional (MiRo) or kinematic (the ball)."""

    def __init__(self, sim, model, options):
        DrivePlugin.__init__(self, sim, model, PlanarMove(sim.physics, model.name, options,
                                                          sim.world.bounds))

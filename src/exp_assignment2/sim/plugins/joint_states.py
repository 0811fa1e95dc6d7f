"""``libgazebo_ros_joint_state_publisher.so``: ``<ns>/joint_states`` of the
joints named in ``jointName`` (comma-separated; every movable joint when
absent) at ``updateRate`` Hz of simulated time."""
import rospy
from sensor_msgs.msg import JointState

from exp_assignment2.sim.plugins.base import Plugin, PluginError
from exp_assignment2.sim.plugins.cores import Every
from exp_assignment2.sim.plugins.ros_io import joint_claims, publish_joint_states


class JointStatePublisherPlugin(Plugin):
    """gazebo_ros_joint_state_publisher: jointName, updateRate."""

    FILENAMES = ('libgazebo_ros_joint_state_publisher.so',)

    def load(self):
        names = [n.strip() for n in self.options.text('jointName').split(',') if n.strip()]
        missing = [n for n in names if not self.model.has_joint(n)]
        if missing:
            raise PluginError('%s: no joint %s in the model' % (self.options.where,
                                                                ', '.join(missing)))
        self.joints = names or None
        self.every = Every(self.options.number('updateRate', 100.0),
                           lambda: self.engine.time)
        self.pub = rospy.Publisher(self.topic('joint_states'), JointState, queue_size=10)
        joint_claims(self.engine, self.topic('joint_states'))[self] = set(
            self.joints or self.model.movable_joints)

    def after_step(self):
        if self.every.due():
            publish_joint_states(self.pub, self.model, self.engine, self.joints)

    def reset(self):
        self.every.reset()

    def close(self):
        self.pub.unregister()
        joint_claims(self.engine, self.topic('joint_states')).pop(self, None)

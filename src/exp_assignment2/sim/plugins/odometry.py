"""``<ns>/odom`` and TF ``odom -> base_frame``: the body's true pose (as
Gazebo's plugins with odometrySource world), twist in the body's frame."""
import rospy
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Odometry
from tf2_msgs.msg import TFMessage


class OdometryPlugin(object):
    """Publishes at ``rate`` Hz of simulated time."""

    def __init__(self, sim, model, options):
        self.sim, self.model = sim, model
        self.frame, self.tf = options['frame'], options['tf']
        self.period, self.next = 1.0 / options['rate'], 0.0
        self.pub = rospy.Publisher(model.topic(options['topic']), Odometry, queue_size=10)
        self.tf_pub = rospy.Publisher('/tf', TFMessage, queue_size=100) if self.tf else None

    def after_step(self, stamp):
        physics = self.sim.physics
        if physics.time + 1e-9 < self.next:
            return
        self.next += self.period
        name = self.model.name
        drive = self.sim.drives.get(name)
        pos, quat = physics.base_pose(name)
        lin, ang = physics.base_twist(name, drive.current() if drive else (0.0, 0.0, 0.0))
        odom = Odometry()
        odom.header.stamp, odom.header.frame_id = stamp, self.frame
        odom.child_frame_id = self.model.base_frame
        pose, twist = odom.pose.pose, odom.twist.twist
        pose.position.x, pose.position.y, pose.position.z = pos
        (pose.orientation.x, pose.orientation.y, pose.orientation.z,
         pose.orientation.w) = quat
        twist.linear.x, twist.linear.y, twist.linear.z = lin
        twist.angular.x, twist.angular.y, twist.angular.z = ang
        self.pub.publish(odom)
        if self.tf_pub is not None:
            tf = TransformStamped(header=odom.header, child_frame_id=odom.child_frame_id)
            t = tf.transform.translation
            t.x, t.y, t.z = pos
            tf.transform.rotation = pose.orientation
            self.tf_pub.publish(TFMessage(transforms=[tf]))

    def reset(self):
        self.next = self.sim.physics.time

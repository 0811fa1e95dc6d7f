"""What the ROS plugins share: stamps, update rates, a velocity command
topic, odometry with its TF (as Gazebo's drive plugins publish it)."""
import rospy
from geometry_msgs.msg import TransformStamped, Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState
from std_msgs.msg import Header
from tf2_msgs.msg import TFMessage

from exp_assignment2.grammar import show_numbers
from exp_assignment2.refusal import RefusalLog


def stamp(engine):
    """The engine's simulated time as a rospy.Time (exact, from integer ns)."""
    ns = engine.time_ns
    return rospy.Time(ns // 1000000000, ns % 1000000000)


class Watched(rospy.SubscribeListener):
    """A publisher that knows, by rospy's events, whether anyone subscribes;
    ``on_change()`` is called when that changes."""

    def __init__(self, topic, cls, on_change=None, queue_size=1):
        rospy.SubscribeListener.__init__(self)
        self.on_change, self.count = on_change, 0
        self.pub = rospy.Publisher(topic, cls, queue_size=queue_size, subscriber_listener=self)
        # a subscriber that connected as rospy registered the topic, before it
        # knew of this listener, brought no event (the camera then never drew
        # for a state machine that was already waiting): count it now
        self.count = max(self.count, self.pub.get_num_connections())
        if self.count and self.on_change is not None:
            self.on_change()

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        pub = getattr(self, 'pub', None)     # a subscriber may come before the assignment
        self.count = pub.get_num_connections() if pub is not None else self.count + 1
        if self.on_change is not None:
            self.on_change()

    def peer_unsubscribe(self, topic_name, num_peers):
        self.count = num_peers
        if self.on_change is not None:
            self.on_change()

    @property
    def wanted(self):
        return self.count > 0


def read_as(raw, cls):
    """A raw message (``rospy.AnyMsg``) as a ``cls``; None when it is another type
    (its connection's md5sum is not ``cls``'s: ROS would not have connected the
    two) or does not read as one."""
    header = getattr(raw, '_connection_header', None) or {}
    if header.get('md5sum') not in (None, '*', cls._md5sum):
        return None
    message = cls()
    try:
        message.deserialize(raw._buff)
    except Exception:        # a malformed message: nobody sees it
        return None
    message._connection_header = header
    return message


def subscribe(topic, cls, callback, **kwargs):
    """A ``rospy.Subscriber`` whose ``callback`` always gets a ``cls``. rospy
    shares one subscription per topic in a node, of the first subscriber's
    type: where a grader's relay (:mod:`exp_assignment2.ros.grader_link`, which
    takes any type) subscribed first, what comes is raw; it is read here as
    ``cls``, so that the student's commands reach the world whatever the grader
    records. A message of another type is left out with a warning, as Gazebo's
    plugin would never have been connected to its publisher."""
    wrong = RefusalLog(topic, rospy.logwarn, period=5.0, what='ignored')

    def typed(message):
        if isinstance(message, rospy.AnyMsg):
            raw, message = message, read_as(message, cls)
            if message is None:
                wrong('a %s is not a %s: ignored' % (
                    (getattr(raw, '_connection_header', None) or {}).get('type', '?'),
                    cls._type))
                return
        callback(message)
    return rospy.Subscriber(topic, cls, typed, **kwargs)


class CommandTopic(object):
    """A Twist topic feeding a VelocityCommand in the simulation thread;
    non-finite commands are ignored and excessive ones clamped, each with a
    warning at most every 5 s per topic."""

    def __init__(self, plugin, topic, command):
        self.engine, self.command, self.topic = plugin.engine, command, topic
        self.ignored = RefusalLog(topic, rospy.logwarn, period=5.0, what='ignored')
        self.clamped = RefusalLog(topic, rospy.logwarn, period=5.0, what='clamped')
        self.sub = subscribe(topic, Twist, self._on_twist, queue_size=1)

    def _on_twist(self, msg):
        values = (msg.linear.x, msg.linear.y, msg.angular.z)
        self.engine.call_soon(lambda: self._take(values))

    def _take(self, values):
        try:
            clamped = self.command.command(*values)
        except ValueError as exc:
            self.ignored('ignored: %s' % exc)
            return
        if clamped:
            self.clamped('%s clamped to the limits, %s'
                         % (show_numbers(values), self.command.limits))

    def close(self):
        self.sub.unregister()


class OdometryPublisher(object):
    """``nav_msgs/Odometry`` of a model and the TF ``frame -> child``: the
    pose of the model's URDF root frame, the twist in the child frame."""

    def __init__(self, topic, frame, child, tf=True):
        self.frame, self.child = frame, child
        self.pub = rospy.Publisher(topic, Odometry, queue_size=10)
        self.tf_pub = rospy.Publisher('/tf', TFMessage, queue_size=100) if tf else None

    def publish(self, when, position, quaternion, linear, angular):
        odom = Odometry()
        odom.header.stamp, odom.header.frame_id = when, self.frame
        odom.child_frame_id = self.child
        pose, twist = odom.pose.pose, odom.twist.twist
        pose.position.x, pose.position.y, pose.position.z = position
        (pose.orientation.x, pose.orientation.y, pose.orientation.z,
         pose.orientation.w) = quaternion
        twist.linear.x, twist.linear.y, twist.linear.z = linear
        twist.angular.x, twist.angular.y, twist.angular.z = angular
        self.pub.publish(odom)
        if self.tf_pub is not None:
            tf = TransformStamped(header=odom.header, child_frame_id=self.child)
            t = tf.transform.translation
            t.x, t.y, t.z = position
            tf.transform.rotation = pose.orientation
            self.tf_pub.publish(TFMessage(transforms=[tf]))

    def close(self):
        self.pub.unregister()
        if self.tf_pub is not None:
            self.tf_pub.unregister()


def joint_claims(engine, topic):
    """Which joints plugins publish on the JointState ``topic`` themselves
    ({plugin: joint names}): the joint_state_controller leaves them out, so
    that no joint comes twice with one stamp (robot_state_publisher's
    TF_REPEATED_DATA warnings; Gazebo's controller publishes only the joints
    of transmissions, so the diff drive's wheels never came twice there)."""
    return engine.shared(('joint_states', topic), dict)


def publish_joint_states(pub, model, engine, names=None):
    """``sensor_msgs/JointState`` of ``names`` (every movable joint by default) now."""
    names, positions, velocities, efforts = model.joint_states(names)
    pub.publish(JointState(header=Header(stamp=stamp(engine)), name=names, position=positions,
                           velocity=velocities, effort=efforts))

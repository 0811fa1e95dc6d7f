"""Gazebo's drive plugins with their ROS topics: ``libgazebo_ros_diff_drive.so``,
``libgazebo_ros_skid_steer_drive.so`` and ``libgazebo_ros_planar_move.so``,
with the options and defaults of gazebo_ros_pkgs (what changed between ROS
releases: :mod:`..releases`). Each subscribes its command topic, keeps the
last command until another comes (as Gazebo's), and publishes odometry and TF
at its rate; the driving itself is the ROS-free core (:mod:`.cores`)."""
import rospy
from geometry_msgs.msg import TransformStamped
from sensor_msgs.msg import JointState
from std_msgs.msg import Header
from tf2_msgs.msg import TFMessage

from exp_assignment2.geometry import quaternion_from_yaw
from exp_assignment2.sim.releases import tf_resolve
from exp_assignment2.sim.plugins.cores import (DiffDriveCore, Every, PlanarMoveCore,
                                               SkidSteerDriveCore)
from exp_assignment2.sim.plugins.ros_io import (CommandTopic, OdometryPublisher, joint_claims,
                                                stamp)


class DiffDrivePlugin(DiffDriveCore):
    """``libgazebo_ros_diff_drive.so`` (see :class:`~.cores.DiffDriveCore`) with
    commandTopic, odometryTopic, odometryFrame, robotBaseFrame, publishTf,
    publishOdomTF, publishWheelTF, publishWheelJointState. Its frames are
    prefixed with the robot namespace where the release did (Kinetic,
    Melodic). Sets the parameter ``<ns>/turn_sign`` (+1: +angular.z turns
    left) for nodes that must know."""

    def load(self):
        DiffDriveCore.load(self)
        o, release = self.options, self.engine.release
        base = release.frame(o.text('robotBaseFrame', 'base_footprint'), self.namespace)
        self.odometry = None
        if o.boolean('publishTf', True):     # every release: no publishTf, no odometry at all
            self.odometry = OdometryPublisher(self.topic(o.text('odometryTopic', 'odom')),
                                              release.frame(o.text('odometryFrame', 'odom'),
                                                            self.namespace), base,
                                              tf=o.boolean('publishOdomTF', True))
        self.wheel_states = None
        if o.boolean('publishWheelJointState', False):
            self.wheel_states = rospy.Publisher(self.topic('joint_states'), JointState,
                                                queue_size=10)
            joint_claims(self.engine, self.topic('joint_states'))[self] = set(self.drive.joints)
        self.wheel_tf = (rospy.Publisher('/tf', TFMessage, queue_size=100)
                         if o.boolean('publishWheelTF', False) else None)
        self.cmd = CommandTopic(self, self.command_topic(), self.command)
        rospy.set_param(self.topic('turn_sign'), self.drive.turn_sign())

    def on_update(self):
        when = stamp(self.engine)
        if self.odometry is not None:
            if self.encoder is not None:
                x, y, yaw = self.encoder.pose
                vx, vy, w = self.encoder.twist
                self.odometry.publish(when, (x, y, 0.0), quaternion_from_yaw(yaw), (vx, vy, 0.0),
                                      (0.0, 0.0, w))
            else:
                position, quaternion = self.model.pose()
                linear, angular = self.model.twist()
                self.odometry.publish(when, position, quaternion, linear, angular)
        if self.wheel_states is not None:
            names, pos, vel, eff = self.model.joint_states(self.drive.joints)
            self.wheel_states.publish(JointState(header=Header(stamp=when), name=names,
                                                 position=pos, velocity=vel, effort=eff))
        if self.wheel_tf is not None:
            self._publish_wheel_tf(when)

    def _publish_wheel_tf(self, when):
        transforms = []
        for name in self.drive.joints:
            joint = self.model.urdf.joints[name]
            (x, y, z), q = self.model.relative_pose(joint.parent, joint.child)
            frame = self.engine.release.frame      # the release's tf prefix, as the odometry's
            tf = TransformStamped(header=Header(stamp=when, frame_id=frame(joint.parent,
                                                                           self.namespace)),
                                  child_frame_id=frame(joint.child, self.namespace))
            t, r = tf.transform.translation, tf.transform.rotation
            t.x, t.y, t.z = x, y, z
            r.x, r.y, r.z, r.w = q
            transforms.append(tf)
        self.wheel_tf.publish(TFMessage(transforms=transforms))

    def close(self):
        self.cmd.close()
        if self.odometry is not None:
            self.odometry.close()
        for pub in (self.wheel_states, self.wheel_tf):
            if pub is not None:
                pub.unregister()
        joint_claims(self.engine, self.topic('joint_states')).pop(self, None)


class SkidSteerDrivePlugin(SkidSteerDriveCore):
    """``libgazebo_ros_skid_steer_drive.so`` (see :class:`~.cores.SkidSteerDriveCore`)
    with commandTopic, odometryTopic, odometryFrame, robotBaseFrame and
    broadcastTF (false): odometry at the update rate, its frames resolved
    against the ``tf_prefix`` parameter, not the namespace, in every release."""

    def load(self):
        SkidSteerDriveCore.load(self)
        o = self.options
        self.odometry = OdometryPublisher(self.topic(o.text('odometryTopic', 'odom')),
                                          tf_resolve('', o.text('odometryFrame', 'odom')),
                                          tf_resolve('', o.text('robotBaseFrame',
                                                                'base_footprint')),
                                          tf=o.boolean('broadcastTF', False))
        self.cmd = CommandTopic(self, self.command_topic(), self.command)
        rospy.set_param(self.topic('turn_sign'), self.drive.turn_sign())

    def on_update(self):
        position, quaternion = self.model.pose()
        linear, angular = self.model.twist()
        self.odometry.publish(stamp(self.engine), position, quaternion,
                              (linear[0], linear[1], 0.0), (0.0, 0.0, angular[2]))

    def close(self):
        self.cmd.close()
        self.odometry.close()


class PlanarMovePlugin(PlanarMoveCore):
    """``libgazebo_ros_planar_move.so`` (see :class:`~.cores.PlanarMoveCore`)
    with commandTopic, odometryTopic, odometryFrame, odometryRate (0 or less:
    no odometry, as Gazebo's), robotBaseFrame, publishOdometryTf."""

    def load(self):
        PlanarMoveCore.load(self)
        o = self.options
        rate = o.number('odometryRate', 20.0)
        self.every = Every(rate, lambda: self.engine.time) if rate > 0 else None
        self.odometry = OdometryPublisher(self.topic(o.text('odometryTopic', 'odom')),
                                          o.text('odometryFrame', 'odom'),
                                          o.text('robotBaseFrame', 'base_footprint'),
                                          tf=o.boolean('publishOdometryTf', True))
        self.cmd = CommandTopic(self, self.command_topic(), self.command)

    def after_step(self):
        if self.every is not None and self.every.due():
            position, quaternion = self.model.pose()
            linear, angular = self.model.twist()
            self.odometry.publish(stamp(self.engine), position, quaternion, linear, angular)

    def reset(self):
        PlanarMoveCore.reset(self)
        if self.every is not None:
            self.every.reset()

    def close(self):
        self.cmd.close()
        self.odometry.close()

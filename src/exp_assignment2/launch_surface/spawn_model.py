"""gazebo_ros' ``spawn_model``: put a model into the running simulator.

The command line is read by :mod:`.spawn_args`. The model XML comes from a
file, a parameter (resolved in the node's namespace, as rospy does), the
model database (``-database``: an include of ``model://NAME``) or stdin,
and goes to ``<gazebo ns>/spawn_urdf_model`` or ``spawn_sdf_model`` with the
robot namespace (default: this node's namespace, as gazebo_ros does), so the
plugins its ``<gazebo>`` tags name come up there. Every wait for the
simulator is bounded by ``-timeout`` and ends when roslaunch stops the node
(:mod:`.stopping`). It logs Gazebo's lines and exits 0 on success, 1 with
the status message on failure (2: a command line it refuses).
"""
import sys
import threading

import rospy
from gazebo_msgs.msg import ModelStates
from gazebo_msgs.srv import DeleteModel, SetModelConfiguration, SpawnModel
from geometry_msgs.msg import Point, Pose, Quaternion
from std_srvs.srv import Empty

from exp_assignment2.launch_surface import spawn_args
from exp_assignment2.launch_surface.stopping import Stop
from exp_assignment2.sim import releases


class SpawnModelNode(object):
    """One spawn_model run, as options say."""

    def __init__(self, options, stop):
        self.options, self.stop = options, stop
        self.gazebo = options.gazebo_namespace

    def wait_for(self, service):
        """Wait for one of the simulator's services, at most -timeout s."""
        rospy.loginfo('Waiting for service %s', service)
        if not self.stop.wait_for_service(service, self.options.timeout):
            if self.stop:
                return False
            rospy.logerr('%s did not appear within %g s: is the simulator (gzserver) '
                         'running? (-timeout S waits longer)', service, self.options.timeout)
            return False
        return True

    def model_xml(self):
        """The model XML from its source, or None after an error line."""
        o = self.options
        if o.source == 'file':
            rospy.loginfo('Loading model XML from file %s', o.source_value)
            try:
                with open(o.source_value) as f:
                    xml = f.read()
            except (IOError, OSError) as exc:
                rospy.logfatal('Error: cannot read file %s: %s', o.source_value, exc.strerror)
                return None
        elif o.source == 'param':
            rospy.loginfo('Loading model XML from ros parameter %s', o.source_value)
            xml = rospy.get_param(o.source_value, '')
            if not isinstance(xml, str):
                xml = ''
        elif o.source == 'database':
            rospy.loginfo('Loading model XML from Gazebo Model Database')
            xml = spawn_args.database_xml(o.source_value)
        else:
            rospy.loginfo('Loading model XML from stdin')
            xml = sys.stdin.read()
        if not xml.strip():
            rospy.logerr('Error: %s %s is empty or does not exist', o.source, o.source_value or '')
            return None
        try:
            return spawn_args.checked_xml(xml, o.package_to_model)
        except ValueError as exc:
            rospy.logerr('%s', exc)
            return None

    def wait_for_model(self):
        """-wait MODEL: until MODEL is in model_states (at most -timeout s)."""
        seen = threading.Event()
        name = self.options.wait

        def on_states(msg):
            if name in msg.name:
                seen.set()
        sub = rospy.Subscriber(self.gazebo + '/model_states', ModelStates, on_states)
        rospy.loginfo('Waiting for model %s before proceeding.', name)
        found = self.stop.wait(seen, self.options.timeout)
        sub.unregister()
        if not found and not self.stop:
            rospy.logerr('model %s did not appear in %s/model_states within %g s', name,
                         self.gazebo, self.options.timeout)
        return found

    def call(self, name, kind, *request):
        """Call one of the simulator's services; its response, or None."""
        service = '%s/%s' % (self.gazebo, name)
        if not self.wait_for(service):
            return None
        rospy.loginfo('Calling service %s', service)
        try:
            return rospy.ServiceProxy(service, kind)(*request)
        except (rospy.ServiceException, rospy.ROSException) as exc:
            rospy.logerr('Service call failed: %s', exc)
            return None

    def run(self):
        """Spawn; 0 on success, 1 on failure."""
        o = self.options
        if o.wait and not self.wait_for_model():
            return 1
        xml = self.model_xml()
        if xml is None:
            return 1
        x, y, z, roll, pitch, yaw = o.pose
        pose = Pose(Point(x, y, z), Quaternion(*spawn_args.quaternion(roll, pitch, yaw)))
        namespace = o.robot_namespace if o.robot_namespace is not None \
            else rospy.get_namespace()
        resp = self.call('spawn_%s_model' % o.format, SpawnModel, o.model, xml, namespace,
                         pose, o.reference_frame)
        if resp is None:
            return 1
        rospy.loginfo('Spawn status: %s', resp.status_message)
        if not resp.success:
            rospy.logerr('Spawn service failed. Exiting.')
            return 1
        if o.joints:
            resp = self.call('set_model_configuration', SetModelConfiguration, o.model, '',
                             [j[0] for j in o.joints], [j[1] for j in o.joints])
            if resp is not None:
                rospy.loginfo('Set model configuration status: %s', resp.status_message)
            if resp is None or not resp.success:
                rospy.logerr('SetModelConfiguration service failed. Exiting.')
                return 1
        if o.unpause:
            rospy.loginfo('Unpausing physics')
            if self.call('unpause_physics', Empty) is None:
                return 1
        if o.bond:
            rospy.loginfo('Waiting for shutdown to delete model %s', o.model)
            self.stop.wait()
            self.delete_model()
        return 0

    def delete_model(self):
        """-b: take the model out again when this node is stopped."""
        rospy.loginfo('Deleting model %s', self.options.model)
        try:
            rospy.ServiceProxy(self.gazebo + '/delete_model', DeleteModel)(self.options.model)
        except (rospy.ServiceException, rospy.ROSException) as exc:
            rospy.logerr('Delete model service call failed: %s', exc)


def release_name():
    """The ROS release the simulator follows (EXP2_ROS_RELEASE), whose spawn_model
    reads the command line; a bad value is the simulator's to refuse."""
    try:
        return releases.choose().name
    except releases.ReleaseError:
        return releases.DEFAULT


def main(argv=None):
    """The spawn_model executable: exit status as described above."""
    argv = rospy.myargv(sys.argv if argv is None else argv)[1:]
    if '-h' in argv or '--help' in argv:
        print(spawn_args.USAGE)
        return 0
    try:
        options = spawn_args.parse(argv, release_name())
    except spawn_args.UsageError as exc:
        print(str(exc), file=sys.stderr)
        return 2
    if options.ignored:
        print('spawn_model: %s ignored (as the spawn_model of ROS kinetic ignored them)'
              % ' '.join(options.ignored), flush=True)
    stop = Stop()
    rospy.init_node('spawn_model', anonymous=True, disable_signals=True)
    status = SpawnModelNode(options, stop).run()
    rospy.signal_shutdown('spawn_model done')
    return status

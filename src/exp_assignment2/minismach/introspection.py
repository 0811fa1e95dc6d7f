"""smach_ros's IntrospectionServer and IntrospectionClient over
:mod:`exp_assignment2.minismach`: what smach_viewer reads, and sets.

As smach_ros does, each container of the tree (the root at ``path``, nested
ones at ``path/LABEL``) publishes its structure (children, transitions,
outcomes) on ``<server_name>/smach/container_structure`` and its status
(initial and active states, userdata) on ``<server_name>/smach/container_status``:
at start, at each of its transitions, and every 2 s of ROS time for a viewer
that comes later. A command on ``<server_name>/smach/container_init`` for its
path sets its initial states and userdata (answered with a status). The
messages are ``smach_msgs``' (a stand-in where Debian lacks it,
tools/stand_ins/smach_msgs); without smach_msgs the server publishes nothing.

:class:`IntrospectionClient` is the other side: the servers running, and a
container's initial state set remotely, as smach_ros's.
"""
import base64
import pickle

import rospy
from std_msgs.msg import Header

from .ros_util import as_duration
from .states import UserData

STATUS_TOPIC = '/smach/container_status'
STRUCTURE_TOPIC = '/smach/container_structure'
INIT_TOPIC = '/smach/container_init'
HEARTBEAT = 2.0         # s of ROS time, smach_ros' update rate


def internal_edges(container):
    """[(outcome, from label, to label)] of a container's transitions."""
    edges = getattr(container, 'get_internal_edges', None)
    if edges is not None:
        return list(edges())
    table = getattr(container, '_transitions', {})
    return [(outcome, label, target) for label in sorted(table)
            for outcome, target in sorted(table[label].items()) if target is not None]


def _pickled(userdata):
    try:
        data = dict(getattr(userdata, '_data', {}))
        return base64.b64encode(pickle.dumps(data, 2)).decode('utf-8')
    except Exception:       # userdata that cannot be pickled: the viewer gets none
        return base64.b64encode(pickle.dumps({}, 2)).decode('utf-8')


def _unpickled(local_data):
    """The userdata dict of a status or init message (smach_ros' encoding)."""
    return pickle.loads(base64.b64decode(local_data))


class ContainerProxy(object):
    """Publishes one container's structure and status."""

    def __init__(self, messages, server_name, container, path):
        self.structure_cls, self.status_cls, init_cls = messages
        self.container, self.path = container, path
        self.init_sub = rospy.Subscriber(server_name + INIT_TOPIC, init_cls, self._on_init)
        self.structure_pub = rospy.Publisher(server_name + STRUCTURE_TOPIC, self.structure_cls,
                                             queue_size=10)
        self.status_pub = rospy.Publisher(server_name + STATUS_TOPIC, self.status_cls,
                                          queue_size=10)
        register = getattr(container, 'register_transition_cb', None)
        if register is not None:
            register(lambda *args: self.publish_status('transition'))
        self.timer = None

    def start(self):
        self.publish_structure()
        self.publish_status('Initial state')
        self.timer = rospy.Timer(rospy.Duration(HEARTBEAT), self._heartbeat)

    def stop(self):
        if self.timer is not None:
            self.timer.shutdown()
            self.timer = None
        self.init_sub.unregister()

    def _on_init(self, msg):
        """A client's initial states and userdata for this container."""
        if msg.path != self.path:
            return
        children = self.container.get_children()
        if not all(label in children for label in msg.initial_states):
            rospy.logerr("Attempting to set initial state in container '%s' to '%s', but this "
                         "container only has states: %s"
                         % (self.path, list(msg.initial_states), sorted(children)))
            return
        set_initial_state = getattr(self.container, 'set_initial_state', None)
        if set_initial_state is None:       # a Concurrence, an Iterator: SMACH's only warn
            rospy.logwarn("Container '%s' cannot have its initial state set" % self.path)
            return
        ud = UserData()
        ud.update(_unpickled(msg.local_data))
        set_initial_state(list(msg.initial_states), ud)
        self.publish_status('REMOTE_INIT')

    def _heartbeat(self, _event):
        self.publish_structure()
        self.publish_status('HEARTBEAT')

    def publish_structure(self):
        edges = internal_edges(self.container)
        self.structure_pub.publish(self.structure_cls(
            Header(stamp=rospy.Time.now()), self.path, list(self.container.get_children()),
            [str(e[0]) for e in edges], [str(e[1]) for e in edges], [str(e[2]) for e in edges],
            list(self.container.get_registered_outcomes())))

    def publish_status(self, info):
        get = lambda name: list(getattr(self.container, name, lambda: [])() or [])  # noqa: E731
        self.status_pub.publish(self.status_cls(
            Header(stamp=rospy.Time.now()), self.path, get('get_initial_states'),
            get('get_active_states'), _pickled(self.container.userdata), info))


class IntrospectionServer(object):
    """``IntrospectionServer(server_name, state, path)``, as smach_ros's."""

    def __init__(self, server_name, state, path):
        self._server_name, self._state, self._path = server_name, state, path
        self._proxies = []

    def start(self):
        try:
            from smach_msgs.msg import (SmachContainerInitialStatusCmd, SmachContainerStatus,
                                        SmachContainerStructure)
        except ImportError:
            rospy.logdebug('IntrospectionServer %s: no smach_msgs, so nothing is published',
                           self._server_name)
            return
        if not rospy.core.is_initialized() or not hasattr(self._state, 'get_children'):
            return      # no node (nothing could be published), or not a container
        self._construct((SmachContainerStructure, SmachContainerStatus,
                         SmachContainerInitialStatusCmd), self._state, self._path)

    def _construct(self, messages, container, path):
        proxy = ContainerProxy(messages, self._server_name, container, path)
        prefix = '' if path == '/' else path
        for label, child in container.get_children().items():
            if hasattr(child, 'get_children'):
                self._construct(messages, child, prefix + '/' + label)
        proxy.start()
        self._proxies.append(proxy)

    def stop(self):
        for proxy in self._proxies:
            proxy.stop()

    def clear(self):
        self._proxies = []


class IntrospectionClient(object):
    """smach_ros's IntrospectionClient: what the IntrospectionServers publish."""

    def get_servers(self):
        """The names of the servers publishing a status (``server_name`` of each)."""
        import rostopic
        return [topic[:topic.rfind(STATUS_TOPIC)]
                for topic in rostopic.find_by_type('smach_msgs/SmachContainerStatus')]

    def set_initial_state(self, server, path, initial_states, initial_userdata=None,
                          timeout=None):
        """Set the initial states (and userdata) of the container at ``path`` of
        ``server``. With a ``timeout`` (ROS time): repeat the command until a
        status of that container shows them (True) or the time is out (False);
        without: send it once and return None, as smach_ros does."""
        from smach_msgs.msg import SmachContainerInitialStatusCmd, SmachContainerStatus
        wanted = dict(getattr(initial_userdata, '_data', None) or {})
        command = SmachContainerInitialStatusCmd(path=path, initial_states=list(initial_states),
                                                 local_data=_pickled(initial_userdata))
        heard = []
        sub = rospy.Subscriber(server + STATUS_TOPIC, SmachContainerStatus,
                               lambda msg: heard.append(msg) if msg.path == path else None)
        pub = rospy.Publisher(server + INIT_TOPIC, SmachContainerInitialStatusCmd, queue_size=1)
        pub.publish(command)
        timeout = as_duration(timeout)
        if timeout is None:
            return None
        start = rospy.Time.now()
        try:
            while rospy.Time.now() - start < timeout:
                pub.publish(command)
                if heard and _shows(heard[-1], initial_states, wanted):
                    return True
                rospy.sleep(0.3)
            return False
        finally:
            sub.unregister()
            pub.unregister()


def _shows(status, initial_states, wanted):
    """Does a container's status show these initial states and userdata?"""
    data = _unpickled(status.local_data)
    return (all(label in status.initial_states for label in initial_states) and
            all(key in data and data[key] == value for key, value in wanted.items()))

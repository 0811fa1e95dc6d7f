"""smach_ros's IntrospectionServer over :mod:`exp_assignment2.minismach`: what
smach_viewer reads.

As smach_ros does, each container of the tree (the root at ``path``, nested
ones at ``path/LABEL``) publishes its structure (children, transitions,
outcomes) on ``<server_name>/smach/container_structure`` and its status
(initial and active states, userdata) on ``<server_name>/smach/container_status``:
at start, at each of its transitions, and every 2 s of ROS time for a viewer
that comes later. The messages are ``smach_msgs``' (a stand-in where Debian
lacks it, tools/stand_ins/smach_msgs); without smach_msgs it publishes nothing.
"""
import base64
import pickle

import rospy
from std_msgs.msg import Header

STATUS_TOPIC = '/smach/container_status'
STRUCTURE_TOPIC = '/smach/container_structure'
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


class ContainerProxy(object):
    """Publishes one container's structure and status."""

    def __init__(self, messages, server_name, container, path):
        self.structure_cls, self.status_cls = messages
        self.container, self.path = container, path
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
            from smach_msgs.msg import SmachContainerStatus, SmachContainerStructure
        except ImportError:
            rospy.logdebug('IntrospectionServer %s: no smach_msgs, so nothing is published',
                           self._server_name)
            return
        if not rospy.core.is_initialized() or not hasattr(self._state, 'get_children'):
            return      # no node (nothing could be published), or not a container
        self._construct((SmachContainerStructure, SmachContainerStatus), self._state,
                        self._path)

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

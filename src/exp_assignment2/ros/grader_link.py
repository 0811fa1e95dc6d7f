"""The simulator's side of a grader's run (see
:mod:`exp_assignment2.sim.ground_truth`): where ``EXP2_GRADER_SOCKET`` is set,
the world's ground truth, the cameras' frames and the topics named in
``EXP2_GRADER_TOPICS`` go to the grader outside the sandbox."""
import os

import rospy
import roslib.message

from exp_assignment2.sim.ground_truth import GroundTruth, GroundTruthLink, SOCKET_ENV, \
    TOPICS_ENV
from exp_assignment2.sim.plugins.ros_io import read_as

RTF_ENV = 'EXP2_REAL_TIME_FACTOR'     # the grader's real_time_factor, over the launch file's


def message_dict(message):
    """A ROS message as plain data (lists, numbers, strings)."""
    if hasattr(message, '__slots__'):
        return {name: message_dict(getattr(message, name)) for name in message.__slots__}
    if isinstance(message, (list, tuple)):
        return [message_dict(v) for v in message]
    if isinstance(message, bytes):
        return list(message)
    if hasattr(message, 'to_sec'):
        return message.to_sec()
    return message


class TopicRelay(object):
    """Relays one topic's messages, whatever their type, to the ground truth."""

    def __init__(self, truth, engine, topic):
        self.truth, self.engine, self.topic = truth, engine, topic
        self.sub = rospy.Subscriber(topic, rospy.AnyMsg, self._on_message, queue_size=100)

    def _on_message(self, raw):
        # rospy shares one subscription per topic in a node: on a topic a plugin
        # here takes too (a robot's cmd_vel), what comes is already that type
        message = raw
        if isinstance(raw, rospy.AnyMsg):
            cls = roslib.message.get_message_class(raw._connection_header.get('type', ''))
            message = read_as(raw, cls) if cls is not None else None
            if message is None:      # malformed, or of no type this machine knows
                return
        self.truth.topic(self.engine.time, self.topic, message_dict(message))


def real_time_factor_override(params):
    """The node's parameters, with the grader's real_time_factor where it set one."""
    value = os.environ.get(RTF_ENV)
    if value:
        params = dict(params, real_time_factor=float(value))
    return params


def attach(engine):
    """Start sending the ground truth when a grader asked for it; None otherwise."""
    path = os.environ.get(SOCKET_ENV)
    if not path:
        return None
    try:
        link = GroundTruthLink(path)
    except OSError as exc:
        rospy.logerr('simulator: cannot reach the grader at %s: %s', path, exc)
        return None
    names = [topic.strip() for topic in os.environ.get(TOPICS_ENV, '').split(',')
             if topic.strip()]
    truth = GroundTruth(engine, link)
    relays = {name: TopicRelay(truth, engine, name) for name in names if name.startswith('/')}
    relative = [name for name in names if not name.startswith('/')]

    def follow(model):
        """A relative topic under each model's namespace, as the model comes."""
        for name in relative:
            topic = model.topic(name)
            if topic not in relays:
                relays[topic] = TopicRelay(truth, engine, topic)
    truth.model_listeners.append(follow)
    for model in list(engine.models.values()):     # those described before we listened
        follow(model)
    truth.relays = relays
    engine.step_listeners.append(truth)
    engine.frame_listeners.append(truth.offer_frame)
    rospy.loginfo('simulator: sending the ground truth to the grader (%s)', path)
    return truth

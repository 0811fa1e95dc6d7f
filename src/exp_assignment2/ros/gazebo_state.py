"""Gazebo's state interface over the engine: where models and links are,
and putting them somewhere else.

* services ``~get_model_state``, ``~set_model_state``, ``~get_link_state``,
  ``~set_link_state``; topics ``~set_model_state``, ``~set_link_state``
  (what the template's ball server uses to hide the ball: ``ball_link`` at
  z = 20);
* topics ``~model_states`` and ``~link_states`` (every model and link, world
  frame, names ``model`` and ``model::link``), published at ``rate`` Hz of
  simulated time while someone subscribes.

A link is named ``model::link`` or by its bare name (the first model that
has it, as Gazebo looks names up). Only a model's root link can be placed
(the others follow their joints). Bad input (an unknown model or link, a
pose that is not finite) is refused with one line, throttled per interface.
"""
import rospy
from gazebo_msgs.msg import LinkState, LinkStates, ModelState, ModelStates
from gazebo_msgs.srv import (GetLinkState, GetLinkStateResponse, GetModelState,
                             GetModelStateResponse, SetLinkState, SetLinkStateResponse,
                             SetModelState, SetModelStateResponse)
from geometry_msgs.msg import Point, Pose, Quaternion, Twist, Vector3
from std_msgs.msg import Header

from exp_assignment2.sim.plugins.cores import Every
from exp_assignment2.sim.plugins.ros_io import Watched, stamp, subscribe
from exp_assignment2.sim.poses import (PoseError, check_in_world, entity_pose, from_matrix,
                                       matrix, pose_tuple, relative, split_entity, twist_tuple)


def pose_msg(pose):
    (x, y, z), (qx, qy, qz, qw) = pose
    return Pose(position=Point(x, y, z), orientation=Quaternion(qx, qy, qz, qw))


def twist_msg(twist):
    (vx, vy, vz), (wx, wy, wz) = twist
    return Twist(linear=Vector3(vx, vy, vz), angular=Vector3(wx, wy, wz))


class GazeboState(object):
    """The state services and topics (see the module docstring)."""

    def __init__(self, engine, world, rate=50.0):
        self.engine, self.world = engine, world
        call = engine.call_and_wait
        self.services = [
            rospy.Service('~get_model_state', GetModelState,
                          lambda req: call(lambda: self.get_model(req))),
            rospy.Service('~set_model_state', SetModelState,
                          lambda req: call(lambda: self.set_model(req.model_state,
                                                                  'set_model_state'))),
            rospy.Service('~get_link_state', GetLinkState,
                          lambda req: call(lambda: self.get_link(req))),
            rospy.Service('~set_link_state', SetLinkState,
                          lambda req: call(lambda: self.set_link(req.link_state,
                                                                 'set_link_state'))),
        ]
        self.subscribers = [
            subscribe('~set_model_state', ModelState, lambda msg: engine.call_soon(
                lambda: self.set_model(msg, 'set_model_state topic')), queue_size=10),
            subscribe('~set_link_state', LinkState, lambda msg: engine.call_soon(
                lambda: self.set_link(msg, 'set_link_state topic')), queue_size=10),
        ]
        self.model_states = Watched('~model_states', ModelStates)
        self.link_states = Watched('~link_states', LinkStates)
        self.every = Every(rate, lambda: engine.time)
        engine.step_listeners.append(self._publish)

    # reading
    def get_model(self, req):
        try:
            model = self._model(req.model_name)
            pose = relative(self.engine, model.pose(), req.relative_entity_name)
            twist = self._twist_in(model.world_twist(), req.relative_entity_name)
        except PoseError as exc:
            return GetModelStateResponse(success=False, status_message=self.world.refused(
                'get_model_state', str(exc)))
        return GetModelStateResponse(
            header=Header(stamp=stamp(self.engine), frame_id=req.relative_entity_name),
            pose=pose_msg(pose), twist=twist_msg(twist), success=True,
            status_message='GetModelState: got properties')

    def get_link(self, req):
        try:
            pose = relative(self.engine, entity_pose(self.engine, self._link_name(req.link_name)),
                            req.reference_frame)
        except PoseError as exc:
            return GetLinkStateResponse(success=False, status_message=self.world.refused(
                'get_link_state', str(exc)))
        return GetLinkStateResponse(link_state=LinkState(link_name=req.link_name,
                                                         pose=pose_msg(pose),
                                                         reference_frame=req.reference_frame),
                                    success=True, status_message='GetLinkState: got state')

    def _model(self, name):
        model = self.engine.models.get(name)
        if model is None:
            raise PoseError('there is no model named %r' % name)
        return model

    def _link_name(self, name):
        model_name, link = split_entity(name)
        if link is None and model_name not in self.engine.models:
            return name          # a bare link name: looked up by entity_pose
        return name if link is not None else model_name + '::' + self._model(
            model_name).base_frame

    def _twist_in(self, twist, reference):
        if reference in ('', 'world', 'map', '/world', '/map'):
            return twist
        rot = matrix(entity_pose(self.engine, reference))[:3, :3].T
        return tuple(rot.dot(twist[0])), tuple(rot.dot(twist[1]))

    # writing
    def set_model(self, state, interface):
        try:
            model = self._model(state.model_name)
            self._place(model, state, state.reference_frame)
        except PoseError as exc:
            return SetModelStateResponse(False, self.world.refused(interface, str(exc)))
        return SetModelStateResponse(True, 'SetModelState: set model state done')

    def set_link(self, state, interface):
        try:
            model_name, link = split_entity(state.link_name)
            if link is None:       # a bare link name: the model that has it
                owner = next((m for m in self.engine.models.values()
                              if state.link_name in m.body.links), None)
                if owner is None:
                    raise PoseError('there is no link named %r' % state.link_name)
                model, link = owner, state.link_name
            else:
                model = self._model(model_name)
                if link not in model.body.links:
                    raise PoseError('model %s has no link %r' % (model_name, link))
            if link != model.base_frame:
                raise PoseError('link %s of %s follows its joints: only the root link (%s) '
                                'can be placed' % (link, model.name, model.base_frame))
            self._place(model, state, state.reference_frame)
        except PoseError as exc:
            return SetLinkStateResponse(False, self.world.refused(interface, str(exc)))
        return SetLinkStateResponse(True, 'SetLinkState: set link state done')

    def _place(self, model, state, reference):
        pose, twist = pose_tuple(state.pose), twist_tuple(state.twist)
        position, quat = from_matrix(matrix(entity_pose(self.engine, reference)).dot(
            matrix(pose)))
        check_in_world(self.engine.bounds, position)
        moving = any(v for part in twist for v in part)
        model.set_pose(position, quat, twist=twist if moving else None)

    # the state topics
    def _publish(self, engine):
        watched = (self.model_states.wanted, self.link_states.wanted)
        if not any(watched) or not self.every.due():
            return
        models = list(engine.models.values())
        if watched[0]:
            poses = [m.pose() for m in models]
            self.model_states.pub.publish(ModelStates(
                name=[m.name for m in models], pose=[pose_msg(p) for p in poses],
                twist=[twist_msg(m.world_twist()) for m in models]))
        if watched[1]:
            names, poses = [], []
            for m in models:
                for link in m.body.links:
                    names.append('%s::%s' % (m.name, link))
                    poses.append(pose_msg(m.link_pose(link)))
            self.link_states.pub.publish(LinkStates(name=names, pose=poses,
                                                twist=[Twist() for _ in names]))

    def close(self):
        for service in self.services:
            service.shutdown()
        for sub in self.subscribers:
            sub.unregister()

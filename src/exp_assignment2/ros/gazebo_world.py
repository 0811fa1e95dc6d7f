"""Gazebo's world services over the engine: spawn, delete, pause, reset,
world and model properties (``/gazebo/...`` with the node named ``gazebo``).

Every request is carried out in the simulation thread (the engine's
``call_and_wait``); a refused one answers ``success: false`` with a status
message that says why, logs one line (throttled per service) and changes
nothing. As gazebo_ros' api plugin, ``spawn_sdf_model`` also spawns a URDF
(its ``<robot>`` root says so); ``spawn_urdf_model`` takes URDF only.
"""
import math
import xml.etree.ElementTree as ET

import rospy
from gazebo_msgs.srv import (DeleteModel, DeleteModelResponse, GetModelProperties,
                             GetModelPropertiesResponse, GetWorldProperties,
                             GetWorldPropertiesResponse, SetModelConfiguration,
                             SetModelConfigurationResponse, SpawnModel, SpawnModelResponse)
from std_srvs.srv import Empty, EmptyResponse

from exp_assignment2.ros.log import refusal_log
from exp_assignment2.sim.engine import SpawnError
from exp_assignment2.sim.poses import PoseError, pose_in_world, pose_tuple


class GazeboWorld(object):
    """The world services of the simulator node.

    :param engine: the :class:`~exp_assignment2.sim.engine.Engine`
    :param sdf_to_urdf: ``fn(sdf_text, name) -> urdf_text`` for
        spawn_sdf_model, or None when SDF is not supported
    """

    def __init__(self, engine, sdf_to_urdf=None):
        self.engine, self.sdf_to_urdf = engine, sdf_to_urdf
        self.refuse = {}
        ns = '~'
        self.services = [
            rospy.Service(ns + 'pause_physics', Empty, self._pause),
            rospy.Service(ns + 'unpause_physics', Empty, self._unpause),
            rospy.Service(ns + 'reset_world', Empty, self._reset_world),
            rospy.Service(ns + 'reset_simulation', Empty, self._reset_simulation),
            rospy.Service(ns + 'spawn_urdf_model', SpawnModel, self._spawn_urdf),
            rospy.Service(ns + 'spawn_sdf_model', SpawnModel, self._spawn_sdf),
            rospy.Service(ns + 'delete_model', DeleteModel, self._delete),
            rospy.Service(ns + 'get_world_properties', GetWorldProperties, self._world),
            rospy.Service(ns + 'get_model_properties', GetModelProperties, self._model),
            rospy.Service(ns + 'set_model_configuration', SetModelConfiguration,
                          self._configure),
        ]

    def refused(self, service, text):
        """Log a refusal (throttled per service) and return ``text``."""
        if service not in self.refuse:
            self.refuse[service] = refusal_log(rospy.resolve_name('~' + service))
        self.refuse[service]('refused: %s' % text)
        return text

    # the clock
    def _pause(self, _req):
        self.engine.paused = True
        return EmptyResponse()

    def _unpause(self, _req):
        self.engine.paused = False
        return EmptyResponse()

    def _reset_world(self, _req):
        self.engine.call_and_wait(self.engine.reset_world)
        return EmptyResponse()

    def _reset_simulation(self, _req):
        self.engine.call_and_wait(self.engine.reset_simulation)
        rospy.loginfo('simulator: reset_simulation: the world and the time are back at 0')
        return EmptyResponse()

    # models
    def _spawn_urdf(self, req):
        return self._spawn(req, req.model_xml, 'spawn_urdf_model')

    def _spawn_sdf(self, req):
        if root_tag(req.model_xml) == 'robot':      # gazebo_ros' spawnSDFModel takes URDF too
            return self._spawn(req, req.model_xml, 'spawn_sdf_model')
        if self.sdf_to_urdf is None:
            return SpawnModelResponse(False, self.refused(
                'spawn_sdf_model', 'model %s: SDF models are not supported here' %
                req.model_name))
        try:
            text = self.sdf_to_urdf(req.model_xml, req.model_name)
        except ValueError as exc:
            return SpawnModelResponse(False, self.refused(
                'spawn_sdf_model', 'model %s: %s' % (req.model_name, exc)))
        return self._spawn(req, text, 'spawn_sdf_model')

    def _spawn(self, req, urdf_text, service):
        def spawn():
            pose = pose_in_world(self.engine, pose_tuple(req.initial_pose),
                                 req.reference_frame)
            model = self.engine.spawn(req.model_name, urdf_text, pose,
                                      namespace=req.robot_namespace)
            return len(self.engine.plugins[model.name])
        try:
            n = self.engine.call_and_wait(spawn, timeout=30.0)
        except (SpawnError, PoseError) as exc:
            return SpawnModelResponse(False, self.refused(service, str(exc)))
        rospy.loginfo('simulator: spawned %s (%d plugins)', req.model_name, n)
        return SpawnModelResponse(True, 'SpawnModel: Successfully spawned entity')

    def _delete(self, req):
        try:
            self.engine.call_and_wait(lambda: self.engine.delete(req.model_name))
        except SpawnError as exc:
            return DeleteModelResponse(False, self.refused('delete_model', str(exc)))
        rospy.loginfo('simulator: deleted %s', req.model_name)
        return DeleteModelResponse(True, 'DeleteModel: successfully deleted model')

    def _world(self, _req):
        return GetWorldPropertiesResponse(sim_time=self.engine.time,
                                          model_names=list(self.engine.models),
                                          rendering_enabled=True, success=True,
                                          status_message='GetWorldProperties: got properties')

    def _model(self, req):
        model = self.engine.models.get(req.model_name)
        if model is None:
            return GetModelPropertiesResponse(success=False, status_message=self.refused(
                'get_model_properties', 'there is no model named %r' % req.model_name))
        links = list(model.urdf.links)
        return GetModelPropertiesResponse(
            parent_model_name='', canonical_body_name=model.urdf.root,
            body_names=links, geom_names=['%s::collision' % l for l in links
                                          if model.urdf.links[l].collisions],
            joint_names=list(model.urdf.joints), child_model_names=[],
            is_static=model.static, success=True,
            status_message='GetModelProperties: got properties')

    def _configure(self, req):
        def configure():
            model = self.engine.models.get(req.model_name)
            if model is None:
                raise PoseError('there is no model named %r' % req.model_name)
            if len(req.joint_names) != len(req.joint_positions):
                raise PoseError('%d joint names but %d positions'
                                % (len(req.joint_names), len(req.joint_positions)))
            for name, value in zip(req.joint_names, req.joint_positions):
                if not model.has_joint(name) or not math.isfinite(value):
                    raise PoseError('joint %r = %r: no such joint, or not finite'
                                    % (name, value))
            for name, value in zip(req.joint_names, req.joint_positions):
                model.set_joint_state(name, value)
        try:
            self.engine.call_and_wait(configure)
        except PoseError as exc:
            return SetModelConfigurationResponse(False, self.refused('set_model_configuration',
                                                                     str(exc)))
        return SetModelConfigurationResponse(True, 'SetModelConfiguration: success')

    def close(self):
        for service in self.services:
            service.shutdown()


def root_tag(text):
    """The XML root element's tag, or None when ``text`` is not XML."""
    try:
        return ET.fromstring(text).tag
    except ET.ParseError:
        return None

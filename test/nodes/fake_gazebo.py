#!/usr/bin/env python3
"""A recording stand-in for the simulator's Gazebo API, for
test/launch_surface.test: it answers what spawn_model and the spawner call,
as Gazebo and ros_control answer, and publishes every call it got (latched
JSON on /fake_gazebo/calls) for the checker to read.

* ``/gazebo/spawn_urdf_model``, ``spawn_sdf_model`` (through the package's
  SDF reader, as the simulator does), ``delete_model``,
  ``set_model_configuration``, ``pause_physics``, ``unpause_physics``;
  ``/gazebo/model_states`` (10 Hz, wall time) of the models spawned. A model
  called ``taken`` is refused, as an existing name is by Gazebo.
* ``<ns>/controller_manager/load_controller``, ``switch_controller``,
  ``unload_controller`` for each ``~namespaces`` entry; loading fails when
  ``<ns>/<name>/type`` is not on the parameter server, as in ros_control.
"""
import json
import threading

import rospy
from controller_manager_msgs.srv import (LoadController, LoadControllerResponse,
                                         SwitchController, SwitchControllerResponse,
                                         UnloadController, UnloadControllerResponse)
from gazebo_msgs.msg import ModelStates
from gazebo_msgs.srv import (DeleteModel, DeleteModelResponse, SetModelConfiguration,
                             SetModelConfigurationResponse, SpawnModel, SpawnModelResponse)
from std_msgs.msg import String
from std_srvs.srv import Empty, EmptyResponse

from exp_assignment2.sim.sdf import model_to_urdf


class FakeGazebo(object):
    """Services that record their requests and answer like Gazebo's."""

    def __init__(self, namespaces):
        self.calls, self.models, self.lock = [], {}, threading.Lock()
        self.pub = rospy.Publisher('/fake_gazebo/calls', String, queue_size=1, latch=True)
        self.states = rospy.Publisher('/gazebo/model_states', ModelStates, queue_size=1)
        for name, kind, handler in (
                ('spawn_urdf_model', SpawnModel, self.spawn_urdf),
                ('spawn_sdf_model', SpawnModel, self.spawn_sdf),
                ('delete_model', DeleteModel, self.delete),
                ('set_model_configuration', SetModelConfiguration, self.configure),
                ('pause_physics', Empty, self.clock), ('unpause_physics', Empty, self.clock)):
            rospy.Service('/gazebo/' + name, kind, self.recorded(name, handler))
        for ns in namespaces:
            root = ns.rstrip('/') + '/controller_manager/'
            for name, kind, handler in (('load_controller', LoadController, self.load),
                                        ('switch_controller', SwitchController, self.switch),
                                        ('unload_controller', UnloadController, self.unload)):
                rospy.Service(root + name, kind, self.recorded(root + name, handler, ns))
        rospy.Timer(rospy.Duration(0.1), self.publish_states)

    def recorded(self, name, handler, *extra):
        def serve(req):
            fields = {f: getattr(req, f) for f in req.__slots__}
            if 'initial_pose' in fields:
                p = req.initial_pose
                fields['initial_pose'] = [p.position.x, p.position.y, p.position.z,
                                          p.orientation.x, p.orientation.y, p.orientation.z,
                                          p.orientation.w]
            with self.lock:
                self.calls.append({'service': name, 'request': fields})
                self.pub.publish(String(json.dumps(self.calls)))
            return handler(req, *extra)
        return serve

    def spawn_urdf(self, req):
        if req.model_name == 'taken' or req.model_name in self.models:
            return SpawnModelResponse(False, 'SpawnModel: Failure - entity %s already exists.'
                                      % req.model_name)
        self.models[req.model_name] = req.initial_pose
        return SpawnModelResponse(True, 'SpawnModel: Successfully spawned entity')

    def spawn_sdf(self, req):
        try:
            model_to_urdf(req.model_xml, req.model_name)
        except ValueError as exc:
            return SpawnModelResponse(False, 'model %s: %s' % (req.model_name, exc))
        return self.spawn_urdf(req)

    def delete(self, req):
        ok = self.models.pop(req.model_name, None) is not None
        return DeleteModelResponse(ok, 'DeleteModel: successfully deleted model' if ok else
                                   'DeleteModel: model does not exist')

    def configure(self, req):
        return SetModelConfigurationResponse(True, 'SetModelConfiguration: success')

    def clock(self, req):
        return EmptyResponse()

    def load(self, req, ns):
        return LoadControllerResponse(rospy.has_param('%s/%s/type' % (ns.rstrip('/'), req.name)))

    def switch(self, req, ns):
        return SwitchControllerResponse(True)

    def unload(self, req, ns):
        return UnloadControllerResponse(True)

    def publish_states(self, _event):
        names = list(self.models)
        self.states.publish(ModelStates(name=names, pose=[self.models[n] for n in names]))


if __name__ == '__main__':
    rospy.init_node('gazebo')
    FakeGazebo(rospy.get_param('~namespaces', ['/robot']))
    rospy.spin()

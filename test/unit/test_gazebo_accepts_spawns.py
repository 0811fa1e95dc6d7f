"""What gazebo_ros accepts when a model is spawned, the simulator accepts (no
master: the ROS side faked where it would need one; the workspace's messages):

* two gazebo_ros_control plugins on one namespace (a template's <gazebo> and
  the student's own): the second logs roscpp's refusal of each service and
  runs nothing, the robot spawns, the first serves the controllers;
* gazebo_ros_control's namespace: its robotNamespace, else the spawn's,
  else the model's name;
* spawn_sdf_model given a URDF spawns it (gazebo_ros' spawnSDFModel reads both).
"""
from types import SimpleNamespace

import pytest

pytest.importorskip('controller_manager_msgs')      # the workspace's messages
pytest.importorskip('gazebo_msgs')
from exp_assignment2.ros import gazebo_world  # noqa: E402
from exp_assignment2.sim.engine import Engine  # noqa: E402
from exp_assignment2.sim.plugins import ros_control  # noqa: E402
from fakes import RecordingLog  # noqa: E402

ROBOT = '''<robot name="r">%s
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1"
    iyz="0" izz="0.1"/></inertial><collision><geometry><box size="0.2 0.2 0.2"/></geometry>
    </collision></link>
</robot>'''
CONTROL = ('<gazebo><plugin name="%s" filename="libgazebo_ros_control.so">%s</plugin>'
           '</gazebo>')


class FakeManager(object):
    made = []

    def __init__(self, plugin, ns):
        self.ns, self.closed = ns, False
        FakeManager.made.append(self)

    def discover(self, params, patient=True):
        return []

    def apply(self):
        pass

    def publish(self):
        pass

    def close(self):
        self.closed = True


@pytest.fixture
def engine(monkeypatch):
    FakeManager.made = []
    monkeypatch.setattr(ros_control, 'ControllerManager', FakeManager)
    monkeypatch.setattr(ros_control.param_watch, 'watch_namespace', lambda ns, cb: {})
    monkeypatch.setattr(ros_control.param_watch, 'unwatch_namespace', lambda ns, cb: None)
    eng = Engine(registry={'libgazebo_ros_control.so': ros_control.RosControlPlugin},
                 log=RecordingLog(), real_time_factor=0)
    yield eng
    eng.close()


def test_a_second_ros_control_on_one_namespace_is_refused_its_services_and_the_robot_spawns(
        engine):
    text = ROBOT % (CONTROL % ('template', '<robotNamespace>/robot</robotNamespace>') +
                    CONTROL % ('student', ''))
    engine.spawn('robot', text, namespace='robot')
    assert [m.ns for m in FakeManager.made] == ['/robot']
    assert [p.facts()['serves'] for p in engine.plugins['robot']] == [True, False]
    errors = [t for level, t in engine.log.lines if level == 'error']
    assert errors[0] == (
        'model robot: plugin student (libgazebo_ros_control.so): Tried to advertise a service '
        'that is already advertised in this node [/robot/controller_manager/list_controllers] '
        '(by model robot): this controller manager serves nothing')
    assert [e.split('[')[1].split(']')[0] for e in errors] == [
        '/robot/controller_manager/' + s for s in ros_control.ADVERTISED]
    engine.run_for(0.05)                                 # the inert one steps quietly
    engine.delete('robot')                               # the namespace is free again
    engine.spawn('robot', ROBOT % (CONTROL % ('again', '')), namespace='robot')
    assert [m.ns for m in FakeManager.made] == ['/robot', '/robot']


@pytest.mark.parametrize('own,spawn_ns,expected', [
    ('<robotNamespace>/arm</robotNamespace>', 'robot', '/arm'),     # its own wins
    ('', 'robot', '/robot'),                                         # the spawn's
    ('', '', '/r1'),                                                 # the model's name
])
def test_gazebo_ros_control_namespace_as_gazebo_gives_it(engine, own, spawn_ns, expected):
    engine.spawn('r1', ROBOT % (CONTROL % ('c', own)), namespace=spawn_ns)
    assert [m.ns for m in FakeManager.made] == [expected]


def test_spawn_sdf_model_spawns_a_urdf(monkeypatch):
    spawned = []
    engine = SimpleNamespace(call_and_wait=lambda fn, timeout=None: fn(), models={},
                             spawn=lambda name, text, pose, namespace: spawned.append(
                                 (name, text)) or SimpleNamespace(name=name),
                             plugins={'r': []})
    monkeypatch.setattr(gazebo_world, 'pose_in_world', lambda engine, pose, frame: pose)
    world = object.__new__(gazebo_world.GazeboWorld)
    world.engine, world.sdf_to_urdf, world.refuse = engine, None, {}
    req = SimpleNamespace(model_name='r', model_xml=ROBOT % '', robot_namespace='',
                          initial_pose=SimpleNamespace(
                              position=SimpleNamespace(x=0, y=0, z=0),
                              orientation=SimpleNamespace(x=0, y=0, z=0, w=1)),
                          reference_frame='')
    response = world._spawn_sdf(req)
    assert response.success and spawned == [('r', ROBOT % '')]
    assert gazebo_world.root_tag('<sdf version="1.6"/>') == 'sdf'
    assert gazebo_world.root_tag('<robot') is None

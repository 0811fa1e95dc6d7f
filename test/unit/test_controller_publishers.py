"""The controller manager keeps one publisher per topic while controllers
come and go (fake rospy publishers and services): a joint_state_controller
replaced by a user's YAML that made a new publisher on /robot/joint_states
left its subscribers unconnected in 1 of 10 runs of controllers.test."""
from types import SimpleNamespace

import pytest

pytest.importorskip('controller_manager_msgs')     # the workspace's messages
from exp_assignment2.sim.plugins import controller_manager  # noqa: E402

JSC = 'joint_state_controller/JointStateController'


class FakePublisher(object):
    made = []

    def __init__(self, topic, cls, queue_size=None):
        self.topic, self.unregistered = topic, False
        FakePublisher.made.append(self)

    def unregister(self):
        self.unregistered = True


class FakeService(object):
    def __init__(self, *args):
        pass

    def shutdown(self):
        pass


def test_a_replaced_joint_state_controller_goes_on_with_the_same_publisher(monkeypatch):
    monkeypatch.setattr(controller_manager.rospy, 'Publisher', FakePublisher)
    monkeypatch.setattr(controller_manager.rospy, 'Service', FakeService)
    FakePublisher.made = []
    plugin = SimpleNamespace(model=SimpleNamespace(name='robot'),
                             engine=SimpleNamespace(time=0.0, call_and_wait=None))
    manager = controller_manager.ControllerManager(plugin, '/robot')
    manager.discover({'joint_state_controller': {'type': JSC, 'publish_rate': 50}})
    first = manager.running['joint_state_controller']
    manager.discover({'joint_state_controller': {'type': JSC, 'publish_rate': 20}})
    second = manager.running['joint_state_controller']
    assert second is not first and second.pub is first.pub
    assert [p.topic for p in FakePublisher.made] == ['/robot/joint_states']
    assert not first.pub.unregistered
    manager.close()
    assert first.pub.unregistered


def test_an_unloaded_joint_state_controller_takes_its_topic_away(monkeypatch):
    monkeypatch.setattr(controller_manager.rospy, 'Publisher', FakePublisher)
    monkeypatch.setattr(controller_manager.rospy, 'Service', FakeService)
    FakePublisher.made = []
    plugin = SimpleNamespace(model=SimpleNamespace(name='robot'),
                             engine=SimpleNamespace(time=0.0, call_and_wait=None))
    manager = controller_manager.ControllerManager(plugin, '/robot')
    manager.discover({'joint_state_controller': {'type': JSC, 'publish_rate': 50}})
    assert manager.unload('joint_state_controller')
    assert [p.unregistered for p in FakePublisher.made] == [True]

"""The PlanningAction client's wait for its server (needs Debian's rospy and
the built messages; no master: the ActionClient is a stand-in)."""
import pytest

pytest.importorskip('rospy')
pytest.importorskip('exp_assignment2.msg')

from exp_assignment2.ros import actions  # noqa: E402


class Topic(object):
    def __init__(self):
        self.registered = True

    def unregister(self):
        self.registered = False


class FakeActionClient(object):
    """Finds its server only if it is the ``finds``-th client made."""
    made = []
    finds = 2

    def __init__(self, name, action):
        self.pub_goal, self.pub_cancel = Topic(), Topic()
        self.status_sub, self.result_sub, self.feedback_sub = Topic(), Topic(), Topic()
        FakeActionClient.made.append(self)

    def topics(self):
        return [self.pub_goal, self.pub_cancel, self.status_sub, self.result_sub,
                self.feedback_sub]

    def wait_for_server(self, timeout):
        return len(FakeActionClient.made) >= FakeActionClient.finds


class Clock(object):
    def wait_for_time(self):
        return True


def test_a_client_that_never_finds_its_server_registers_its_topics_again(monkeypatch):
    monkeypatch.setattr(actions.actionlib, 'ActionClient', FakeActionClient)
    monkeypatch.setattr(actions.rospy, 'logwarn', lambda *args: None)
    del FakeActionClient.made[:]
    client = actions.PlanningClient('/robot_reaching_goal', Clock())
    assert client.wait_for_server()
    first, second = FakeActionClient.made
    assert client.client is second
    assert not any(t.registered for t in first.topics())     # let go of before the new one
    assert all(t.registered for t in second.topics())

"""How nodes end (ros/ending.py): an error caused by the shutdown is dropped,
any other is raised, and the process leaves with the right code."""
import pytest

rospy = pytest.importorskip('rospy')
from exp_assignment2.ros import ending  # noqa: E402


class Left(Exception):
    """Stands in for os._exit: carries the exit code."""


@pytest.fixture
def exits(monkeypatch):
    def fake_exit(code):
        raise Left(code)
    monkeypatch.setattr(ending.os, '_exit', fake_exit)


def leave_code(body):
    with pytest.raises(Left) as left:
        ending.run_until_shutdown(body)
    return left.value.args[0]


def fail():
    raise rospy.ROSException('topic was closed during publish()')


def test_a_body_that_returns_leaves_with_0(exits):
    assert leave_code(lambda: None) == 0


def test_an_error_during_shutdown_is_the_end_not_an_error(exits, monkeypatch):
    monkeypatch.setattr(ending.rospy, 'is_shutdown', lambda: True)
    assert leave_code(fail) == 0


def test_an_error_while_running_is_raised(exits, monkeypatch):
    monkeypatch.setattr(ending.rospy, 'is_shutdown', lambda: False)
    with pytest.raises(rospy.ROSException):
        ending.run_until_shutdown(fail)


def test_system_exit_keeps_its_code(exits):
    def stop():
        raise SystemExit(3)
    assert leave_code(stop) == 3

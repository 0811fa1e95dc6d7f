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


def test_a_start_interrupted_by_the_end_of_the_launch_leaves_with_0(exits, monkeypatch):
    def start():
        raise rospy.exceptions.ROSInitException('init_node interrupted before it could complete')
    monkeypatch.setattr(ending.rospy, 'is_shutdown', lambda: True)
    assert leave_code(start) == 0


def test_every_node_script_runs_its_main_here():
    import glob
    import os
    scripts = os.path.join(os.path.dirname(__file__), '..', '..', 'scripts')
    nodes = os.path.join(os.path.dirname(ending.__file__), '..', 'nodes')
    for path in sorted(glob.glob(os.path.join(scripts, '*.py'))):
        name = os.path.basename(path)
        with open(os.path.join(nodes, name)) as f:
            if 'rospy' not in f.read():
                continue
        with open(path) as f:
            assert f.read().rstrip().endswith('run_until_shutdown(main)'), name

"""The simulator's watch for a second /clock publisher: its own messages say
nothing, another node's get one ERROR line naming it, throttled."""
import pytest

pytest.importorskip('rospy')
from exp_assignment2.ros.clock_watch import SecondClock  # noqa: E402


def test_another_publisher_is_named_once_then_counted():
    lines = []
    watch = SecondClock('/gazebo', lambda: 31.35, lines.append)
    for _ in range(100):
        watch.saw('/gazebo', 31.35)
    assert lines == []
    for stamp in (0.0, 2.0 ** 31 - 1, 2.0 ** 32 - 1) * 20:
        watch.saw('/intruder', stamp)
    assert len(lines) == 1
    assert lines[0].startswith("/clock: /intruder publishes it too (its stamp: 0 s; the "
                               "simulator's time: 31.35 s)")
    watch.report.flush()
    assert lines[1] == '/clock: 59 more messages of other publishers in the last 10 s'

"""The head check at the dog's arrivals (exp_assignment2.grading.judge.arrivals,
.behaviours; no ROS), on hand-made ground truth: a dog that came to rest at the
ball and looked both ways, a sweep split by the ball moving on, a long sweep
against short pauses of the ball, and the stops that are no occasion (a ball
hidden as the dog arrives, a pause while the ball rolls past, a ball behind the
dog, a look the run's end cut)."""
import pytest

from exp_assignment2.grading.judge import metrics
from behaviour_traces import HIDDEN, arrives, figure, line, still, sweep, trace


def test_the_head_both_ways_after_the_dog_came_to_rest_at_the_ball():
    ball = lambda t: (4.0, 0.0, 0.5)                                # noqa: E731
    got = figure(trace(arrives(1.2, 10), ball, head=sweep(11, 4)), 'looks_both_ways')
    assert got[0] == 1.0 and 'after 1 of the 1 times' in got[1]
    assert got[2] == pytest.approx(15.0, abs=0.2)       # the second side reached
    one_way = trace(arrives(1.2, 10), ball, head=sweep(11, 4, right=0.5))
    assert figure(one_way, 'looks_both_ways')[0] == 0.0
    # it came to rest 6 m short of it, or with the ball on it: no arrival at the ball
    for rest_at in (-2.0, 3.8):
        with pytest.raises(metrics.NotJudged, match='never came to rest within 3.2 m'):
            figure(trace(arrives(rest_at, 10), ball, head=sweep(11, 4)), 'looks_both_ways')
    # a dog spawned beside the ball, which never came to it, has no occasion either
    with pytest.raises(metrics.NotJudged, match='did not come there'):
        figure(trace(still(1.2), ball, head=sweep(11, 4)), 'looks_both_ways')


def test_a_sweep_split_by_the_ball_moving_on_counts():
    """The student's ball node moved the ball on the moment the dog stopped; it next
    rested behind the dog. The dog looked +0.5 for 4 s, then -0.5 for 4 s: 1 of 1."""
    ball = lambda t: (4.0, 0.0, 0.5) if t < 10 else (  # noqa: E731
        line(4.0, -4.0, 10, 14)(t)[0], 0.0, 0.5)
    got = figure(trace(arrives(1.2, 10), ball, head=sweep(10.5, 4)), 'looks_both_ways')
    assert got[0] == 1.0 and 'after 1 of the 1 times' in got[1]


def test_a_long_sweep_against_short_pauses_of_the_ball_counts_at_every_arrival():
    """Every 40 s the ball stops at a place 6 m on, rests 20 s, and rolls on; the dog
    comes to rest 2.8 m short of it 4 s after it stopped and sweeps its head for 26 s
    (13 s each way), outlasting the ball's pause, then follows: 3 of 3."""
    def ball(t):
        k, since = divmod(t, 40.0)
        return (-5.0 + 6.0 * (k + max(0.0, since - 20.0) / 20.0), 0.0, 0.5)

    def robot(t):
        k, since = divmod(t - 4.0, 40.0)
        if t < 4.0:
            return line(-9.5, -7.8, 2.0, 4.0)(t)
        x = -7.8 + 6.0 * k + 6.0 * min(1.0, max(0.0, (since - 24.5) / 15.5))
        return (x, 0.0, 0.0)

    def head(t):
        since = (t - 4.5) % 40.0
        return 0.6 if 0 <= since < 13 else -0.6 if since < 26 else 0.0
    got = figure(trace(robot, ball, until=120, head=head), 'looks_both_ways')
    assert got[0] == 1.0 and 'after 3 of the 3 times' in got[1], got


def test_a_ball_hidden_as_the_dog_arrives_is_no_occasion():
    """The ball goes under the floor 1 s after the dog came to rest at it: the dog is
    to give it up, not to look around for it."""
    hidden = trace(arrives(1.2, 10), lambda t: (4.0, 0.0, 0.5 if t < 11 else HIDDEN),
                   head=lambda t: 0.0)
    with pytest.raises(metrics.NotJudged, match='the ball was gone as it came'):
        figure(hidden, 'looks_both_ways')


def test_a_pause_while_the_ball_rolls_past_is_no_arrival():
    """The dog pauses 2.8 m from a ball that is still rolling past it: it did not come
    to a ball at rest, so nothing asked it to look around."""
    rolling = trace(arrives(1.2, 10), lambda t: (4.0, -6.0 + 0.5 * t, 0.5), until=40,
                    head=lambda t: 0.0)
    with pytest.raises(metrics.NotJudged, match='the ball was rolling while it rested'):
        figure(rolling, 'looks_both_ways')
    # a ball that rolls to a stop beside the resting dog: arrived at when it stops
    to_a_stop = trace(arrives(1.2, 10), lambda t: (4.0, min(0.0, -6.0 + 0.5 * t), 0.5),
                      until=60, head=sweep(14, 3))
    got = figure(to_a_stop, 'looks_both_ways')
    assert got[0] == 1.0 and got[2] == pytest.approx(17.0, abs=0.2)


def test_a_stop_of_the_ball_behind_the_dog_is_no_occasion():
    """The ball rests behind the dog (out of its camera's view, within reach): the
    dog never came to it; a head still is not failed for it."""
    behind = trace(arrives(-1.0, 10), lambda t: (-3.0, 0.0, 0.5), head=lambda t: 0.0)
    with pytest.raises(metrics.NotJudged, match="out of its camera's view"):
        figure(behind, 'looks_both_ways')


def test_a_look_the_run_s_end_cut_is_an_occasion_only_when_both_sides_came():
    ball = lambda t: (4.0, 0.0, 0.5)                                # noqa: E731
    one_way_then = lambda t: 0.9 * min(1.0, max(0.0, t - 26.0))    # noqa: E731
    cut = trace(arrives(1.2, 23.5), ball, until=30.2, head=one_way_then)
    with pytest.raises(metrics.NotJudged, match='less than 30 s of the run left to look'):
        figure(cut, 'looks_both_ways')
    both = trace(arrives(1.2, 23.5), ball, until=35, head=sweep(25, 3))
    assert figure(both, 'looks_both_ways')[0] == 1.0
    # with its window over before the end, a look one way only is failed
    longer = trace(arrives(1.2, 10), ball, until=45, head=one_way_then)
    got = figure(longer, 'looks_both_ways')
    assert got[0] == 0.0 and 'after 0 of the 1 times' in got[1]

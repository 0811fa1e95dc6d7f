"""plot_run.py's pure parts (scenario, states, hidden stretches) on made-up
data, and the figure they make (test_plot_run_cli.py runs the script)."""
import types

import pytest

from exp_assignment2.plot_run import (DOG, MIRO, PlotError, Run, Track, detect_scenario,
                                      hidden_stretches, is_hidden, labels_at, run_from_messages,
                                      runs, state_changes, state_label, state_segments, summary,
                                      time_in_states)



# --- the pure parts -----------------------------------------------------------

def test_scenario_from_topics():
    assert detect_scenario(['/clock', '/robot/odom', '/ball/odom']) == DOG
    assert detect_scenario(['/odom', '/state', '/arrival']) == MIRO
    for topics in ([], ['/odom'], ['/state'], ['/chatter', '/rosout']):
        with pytest.raises(PlotError) as e:
            detect_scenario(topics)
        assert '/robot/odom' in str(e.value) and '/odom and /state' in str(e.value)


def test_miro_state_names_become_the_short_labels():
    assert [state_label(s) for s in ('SLEEP STATE', 'NORMAL', 'PLAY STATE ', 'PLAY')] == \
        ['SLEEP', 'NORMAL', 'PLAY', 'PLAY']
    assert state_label('DANCING') == 'DANCING'


def test_repeated_latched_states_are_no_change():
    stamped = [(5.0, 'SLEEP'), (0.0, 'NORMAL'), (5.5, 'SLEEP'), (9.0, 'PLAY'), (9.1, 'PLAY')]
    assert state_changes(stamped) == [(0.0, 'NORMAL'), (5.0, 'SLEEP'), (9.0, 'PLAY')]


def test_state_segments_run_to_the_end_and_sum_up():
    changes = [(1.0, 'NORMAL'), (4.0, 'SLEEP'), (10.0, 'NORMAL'), (12.0, 'PLAY')]
    segments = state_segments(changes, 20.0)
    assert segments == [(1.0, 4.0, 'NORMAL'), (4.0, 10.0, 'SLEEP'), (10.0, 12.0, 'NORMAL'),
                        (12.0, 20.0, 'PLAY')]
    assert time_in_states(segments) == {'NORMAL': 5.0, 'SLEEP': 6.0, 'PLAY': 8.0}
    assert state_segments([], 20.0) == []
    assert state_segments([(3.0, 'PLAY')], 2.0) == [(3.0, 3.0, 'PLAY')]


def test_labels_at_times():
    changes = [(1.0, 'NORMAL'), (4.0, 'SLEEP')]
    assert labels_at([0.0, 1.0, 3.9, 4.0, 99.0], changes) == [None, 'NORMAL', 'NORMAL', 'SLEEP',
                                                               'SLEEP']
    assert labels_at([1.0], []) == [None]


def test_runs_join_up_where_the_key_changes():
    pieces = runs([0, 1, 2, 3, 4], [10, 11, 12, 13, 14], ['a', 'a', 'b', 'b', 'a'])
    assert pieces == [('a', [0, 1, 2], [10, 11, 12]), ('b', [2, 3, 4], [12, 13, 14]),
                      ('a', [4], [14])]
    assert runs([], [], []) == []


def test_hidden_is_under_the_ground_or_lifted_to_disappear():
    assert [is_hidden(z) for z in (-1.0, -0.001, 0.0, 0.5, 19.99, 20.0, 25.0)] == \
        [True, True, False, False, False, True, True]


def ball(samples):
    """A Track from [(t, x, y, z)]."""
    track = Track()
    for sample in samples:
        track.append(*sample)
    return track


def test_hidden_stretches_and_their_dotted_pieces():
    track = ball([(0, 0, 0, 0.5), (1, 1, 0, -1.0), (2, 2, 0, -1.0), (3, 3, 0, 0.5),
                  (4, 4, 0, 20.0), (5, 5, 0, 20.0)])
    assert hidden_stretches(track) == [(1, 3), (4, 5)]
    pieces = runs(track.x, track.y, [is_hidden(z) for z in track.z])
    # the hidden ball's x, y still move: the hidden pieces are its path meanwhile
    assert [(hidden, xs) for hidden, xs, _ in pieces] == \
        [(False, [0, 1]), (True, [1, 2, 3]), (False, [3, 4]), (True, [4, 5])]
    assert hidden_stretches(ball([(0, 0, 0, 0.5)])) == []


def fake(**fields):
    """A message stand-in: attributes only, as rosbag's generated classes have."""
    return types.SimpleNamespace(**fields)


def stamp(t):
    return fake(to_sec=lambda: t)


def odom(t, x, y, z=0.0):
    return fake(header=fake(stamp=stamp(t)),
                pose=fake(pose=fake(position=fake(x=x, y=y, z=z))))


def test_messages_become_a_run_in_simulated_time():
    # recorded without use_sim_time: the bag's time is the wall clock (1000 + 2 sim)
    messages = [('/clock', fake(clock=stamp(0.0)), 1000.0),
                ('/state', fake(data='SLEEP STATE'), 1000.5),
                ('/odom', odom(0.5, 1.0, 1.0), 1001.0),
                ('/gesture', fake(header=fake(stamp=stamp(0.0)), person_x=2, person_y=8,
                                  point_x=8, point_y=2), 1002.0),
                ('/state', fake(data='NORMAL'), 1003.0),
                ('/arrival', fake(data=[3, 3, 2.9, 3.1, 1]), 1003.5),
                ('/voice', fake(data='play'), 1004.0),
                ('/odom', odom(2.0, 3.0, 3.0), 1004.0),
                ('/clock', fake(clock=stamp(2.0)), 1004.0)]
    run = run_from_messages('m.bag', MIRO, messages)
    assert run.changes == [(0.25, 'SLEEP'), (1.5, 'NORMAL')]
    assert (run.robot.t, run.robot.x) == ([0.5, 2.0], [1.0, 3.0])
    assert run.arrivals == [(1.75, 3, 3, 2.9, 3.1, 1)] and run.words == [(2.0, 'play')]
    assert run.gestures == [(1.0, 2, 8, 8, 2)]      # no stamp: the bag time, mapped
    assert (run.start, run.end, run.ball) == (0.0, 2.0, None)
    with pytest.raises(PlotError):
        run_from_messages('empty.bag', DOG, [])


def made_up_run():
    robot = ball([(t, 0.5 * t, 0.0, 0.0) for t in range(11)])
    bal = ball([(t, -float(t), 1.0, -1.0 if 3 <= t < 6 else 0.5) for t in range(11)])
    changes = [(0.0, 'NORMAL'), (2.0, 'SLEEP'), (7.0, 'PLAY')]
    return Run('made_up.bag', DOG, 0.0, 10.0, changes, robot, bal)


def test_summary_says_span_states_and_changes():
    text = ' '.join(summary(made_up_run()).split())      # the columns' spacing aside
    assert 'made_up.bag: scenario A' in text and '0.0 .. 10.0 s (10.0 s)' in text
    assert 'SLEEP 5.0 s 50% NORMAL 2.0 s 20% PLAY 3.0 s 30%' in text
    assert '2 state changes; robot path 5.0 m' in text
    assert 'ball hidden: 1 stretches, 3.0 s' in text


def test_figure_draws_hidden_ball_stretches_dotted_and_paths_by_state():
    from exp_assignment2 import run_figure
    fig = run_figure.figure(made_up_run())
    world = fig.axes[0]
    lines = [(l.get_label(), l.get_linestyle(), l.get_color()) for l in world.get_lines()]
    assert ('ball, hidden (z < 0 or z >= 20)', ':', run_figure.BALL_HIDDEN_COLOUR) in lines
    assert ('ball', '-', run_figure.BALL_COLOUR) in lines
    for state in ('NORMAL', 'SLEEP', 'PLAY'):
        assert ('robot: %s' % state, '-', run_figure.STATE_COLOURS[state]) in lines
    assert world.get_aspect() == 1.0 and world.get_xlabel() == 'x [m]'
    assert any('made_up.bag' in t.get_text() and '10 s' in t.get_text() for t in fig.texts)

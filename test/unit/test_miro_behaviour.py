"""MiRo's states on a fake grid and a hand-turned clock: listening, orders,
timings and every transition, no ROS."""
import random

import pytest

from exp_assignment2.behaviour.miro import Miro, MiroNormal, MiroParams, MiroPlay, MiroSleep, \
    build_state_machine
from exp_assignment2.behaviour.person import Ears, Person, SimulatedPerson
from exp_assignment2.grammar import parse_voice
from exp_assignment2.smach_api import report_active_state

from fakes import FakeClock, MiroWorld, RecordingLog


def make_miro(simulate=False, seed=0, **params):
    clock = FakeClock()
    world = MiroWorld(clock, random.Random(seed))
    log = RecordingLog()
    p = MiroParams(lambda k, d: params.get(k, d))
    ears = Ears(clock, log, p.voice_timeout)
    simulated = SimulatedPerson(random.Random(seed)) if simulate else None
    miro = Miro(clock, world, ears, Person(simulated=simulated), p, random.Random(seed), log,
                simulated=simulated)
    return clock, world, miro


def say_at(clock, miro, t, text):
    said = []

    def tick(now, dt):
        if now >= t and not said:
            said.append(now)
            miro.ears.hear(parse_voice(text), text)
    clock.tickers.append(tick)
    return said


def test_sleep_goes_home_rests_and_wakes():
    clock, world, miro = make_miro(sleep_time=4.0)
    assert MiroSleep(miro).execute(None) == 'wake'
    assert world.arrivals() == [(3, 3)]
    arrival = 3 * 2 ** 0.5
    assert clock.now() == pytest.approx(arrival + 4.0, abs=0.1)


def test_asleep_miro_does_not_listen_and_says_so_once():
    clock, world, miro = make_miro()
    say_at(clock, miro, 1.0, 'play')
    say_at(clock, miro, 2.0, 'hey buddy')
    MiroSleep(miro).execute(None)
    lines = [l for l in miro.log.text().splitlines() if 'asleep' in l]
    assert len(lines) == 1 and "'play' not heard" in lines[0]
    assert not miro.ears.has(('play',))


def test_a_call_mid_wander_starts_play_within_one_second_and_abandons_the_wander():
    clock, world, miro = make_miro(sleep_probability=0.0)
    said = say_at(clock, miro, 2.0, 'play')
    assert MiroNormal(miro).execute(None) == 'play'
    assert clock.now() - said[0] <= 1.0
    assert not world.goals[0].done(), 'the wander was not finished'
    assert 'wander is abandoned' in miro.log.text()


def test_normal_wanders_loops_times_then_sleeps():
    clock, world, miro = make_miro(sleep_probability=0.0, loops=3, listen_time=3.0)
    assert MiroNormal(miro).execute(None) == 'sleep'
    assert [c for _, c, _ in world.commands] == ['go_rand'] * 3
    assert len(world.arrivals()) == 3


def test_normal_sleeps_by_chance_after_a_wander():
    clock, world, miro = make_miro(sleep_probability=1.0, loops=3)
    assert MiroNormal(miro).execute(None) == 'sleep'
    assert len(world.commands) == 1


def test_an_order_in_normal_is_not_kept_for_play():
    clock, world, miro = make_miro(sleep_probability=0.0)
    say_at(clock, miro, 1.0, 'go to 6 2')
    say_at(clock, miro, 1.5, 'play')
    assert MiroNormal(miro).execute(None) == 'play'
    assert not miro.ears.has(('go_to',))
    assert 'only counts in PLAY' in miro.log.text()


def test_play_without_any_gesture_goes_to_the_configured_person():
    clock, world, miro = make_miro(loops=1, listen_time=1.0)
    assert MiroPlay(miro).execute(None) == 'normal'
    assert world.commands[0][1:] == ('go to 5 5', (5, 5))
    assert 'points nowhere' in miro.log.text()


def test_an_order_said_on_the_way_to_the_person_is_obeyed_next():
    clock, world, miro = make_miro(loops=1, listen_time=1.0, voice_timeout=10.0)
    say_at(clock, miro, 1.0, 'go to 6 2')      # 7 s from (0, 0) to (5, 5)
    assert MiroPlay(miro).execute(None) == 'normal'
    assert [t for _, _, t in world.commands] == [(5, 5), (6, 2)]
    assert (round(world.x, 2), round(world.y, 2)) == (6.0, 2.0)


def test_an_order_said_during_a_long_drive_is_not_lost():
    clock, world, miro = make_miro(loops=2, listen_time=1.0, voice_timeout=10.0)
    miro.person.saw_gesture((0, 0), (10, 10))
    said = []

    def order_on_the_way(now, dt):
        if len(world.commands) == 2 and not said:    # on the way to (10, 10): 14 s
            said.append(now)
            miro.ears.hear(parse_voice('go to 1 9'))
    clock.tickers.append(order_on_the_way)
    MiroPlay(miro).execute(None)
    assert [t for _, _, t in world.commands] == [(0, 0), (10, 10), (1, 9)]


def test_a_repeated_call_in_play_just_waits():
    clock, world, miro = make_miro(loops=1, listen_time=5.0, wait_time=2.0)
    say_at(clock, miro, 8.0, 'hey buddy')         # after arriving at (5, 5) at ~7.1 s
    assert MiroPlay(miro).execute(None) == 'normal'
    assert len(world.commands) == 1
    assert clock.now() == pytest.approx(8.0 + 2.0, abs=0.1)


def test_silence_follows_the_pointed_place():
    clock, world, miro = make_miro(loops=1, listen_time=2.0)
    miro.person.saw_gesture((4, 4), (8, 2))
    assert MiroPlay(miro).execute(None) == 'normal'
    assert [t for _, _, t in world.commands] == [(4, 4), (8, 2)]
    assert world.arrivals() == [(4, 4), (8, 2)]


def test_a_gesture_made_on_the_way_to_the_person_is_followed():
    clock, world, miro = make_miro(loops=1, listen_time=2.0)

    def point_on_the_way(now, dt):
        if now >= 1.0 and miro.person.gesture is None:    # 7 s from (0, 0) to (5, 5)
            miro.person.saw_gesture((4, 4), (8, 2))
    clock.tickers.append(point_on_the_way)
    assert MiroPlay(miro).execute(None) == 'normal'
    assert [t for _, _, t in world.commands] == [(5, 5), (8, 2)]
    assert 'points at (8, 2)' in miro.log.text()


def test_play_obeys_loops_orders_then_returns_to_normal():
    clock, world, miro = make_miro(loops=3, listen_time=1.0)
    miro.person.saw_gesture((5, 5), (7, 7))
    assert MiroPlay(miro).execute(None) == 'normal'
    assert [t for _, _, t in world.commands] == [(5, 5), (7, 7)] * 3


def test_a_word_is_valid_for_voice_timeout_only():
    clock, world, miro = make_miro(voice_timeout=10.0)
    miro.ears.enter('PLAY')
    miro.ears.hear(parse_voice('go to 1 1'))
    clock.sleep(9.9)
    assert miro.ears.has(('go_to',))
    clock.sleep(0.2)
    assert miro.ears.take(('go_to',)) is None


def test_an_order_said_as_play_ends_gets_a_line_saying_it_came_too_late():
    clock, world, miro = make_miro(loops=1, listen_time=1.0)
    miro.person.saw_gesture((5, 5), (7, 7))

    def order_at_the_end(now, dt):
        if len(world.commands) == 2 and world.arrivals() == [(5, 5), (7, 7)]:
            miro.ears.hear(parse_voice('go to 6 2'), 'go to 6 2')
            clock.tickers.remove(order_at_the_end)
    clock.tickers.append(order_at_the_end)
    assert MiroPlay(miro).execute(None) == 'normal'
    miro.ears.enter('NORMAL')
    late = [l for l in miro.log.text().splitlines() if 'too late' in l]
    assert late == ["PLAY is over: 'go to 6 2' came too late; not kept"]
    assert [t for _, _, t in world.commands] == [(5, 5), (7, 7)]


def test_a_call_before_sleeping_is_not_acted_on_after_waking():
    clock, world, miro = make_miro(sleep_time=1.0)
    miro.ears.enter('NORMAL')
    miro.ears.hear(parse_voice('play'))
    MiroSleep(miro).execute(None)
    miro.ears.enter('NORMAL')
    assert not miro.ears.has(('play',))


def test_the_whole_machine_sleep_normal_play_normal():
    clock, world, miro = make_miro(sleep_probability=0.0, loops=1, listen_time=1.0)
    states = []
    sm = build_state_machine(miro)
    report_active_state(sm, lambda label: states.append(label))
    say_at(clock, miro, 9.0, 'play')            # mid-wander in NORMAL

    def stop(now, dt):
        clock.shut = len(states) >= 5
    clock.tickers.append(stop)
    sm.execute()
    assert states[:5] == ['SLEEP', 'NORMAL', 'PLAY', 'NORMAL', 'SLEEP']


def test_the_simulated_person_plays_when_nobody_talks():
    clock, world, miro = make_miro(simulate=True, seed=2, sleep_probability=0.0, loops=30)
    assert MiroNormal(miro).execute(None) == 'play'
    assert 'the simulated person says' in miro.log.text()


def test_simulated_person_is_seeded_and_speaks_the_grammar():
    a, b = SimulatedPerson(random.Random(7)), SimulatedPerson(random.Random(7))
    said_a = [a.says(playing=i % 2 == 0) for i in range(200)]
    assert said_a == [b.says(playing=i % 2 == 0) for i in range(200)]
    spoken = [s for s in said_a if s]
    assert any(s.startswith('go to') for s in spoken) and {'play', 'hey buddy'} & set(spoken)
    for text in spoken:
        parse_voice(text)
    for _ in range(100):
        (px, py), (gx, gy) = a.gesture()
        assert all(0 <= v <= 10 for v in (px, py, gx, gy))


@pytest.mark.parametrize('bad', [-1, float('nan')])
def test_params_refuse_bad_numbers(bad):
    with pytest.raises(ValueError, match='listen_time'):
        MiroParams(lambda k, d: bad if k == 'listen_time' else d)

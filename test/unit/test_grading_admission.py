"""How many runs at once (exp_assignment2.grading.run.admission) and the
grading's loop that follows it: a run starts only when the cores its
measured cost needs are free, the estimate moving from the profile's figure
to the class's measured runs; a starved run is run again once the others are
done, alone, its page saying why. No ROS, no sandbox, no Dask scheduler (the
stand-in cluster of test_grading_stopping)."""
import json
import os

import pytest

distributed = pytest.importorskip('distributed')
from exp_assignment2.grading import record  # noqa: E402
from exp_assignment2.grading.run import dispatch  # noqa: E402
from exp_assignment2.grading.run.admission import BUSY, Admission, cost, starved  # noqa: E402
from test_grading_stopping import Cluster, came_back, runs_of  # noqa: E402,F401
from test_grading_stopping import no_wait  # noqa: E402,F401 -- the fixture


def ran(cores, sim=200.0, achieved=1.0, asked=1.0):
    """A finished run's measured facts: ``cores`` at real time over ``sim`` s."""
    return {'cpu_s': {'simulator': 0.3 * cores * sim, 'student': 0.7 * cores * sim},
            'truth': {'sim_time': sim}, 'real_time_factor': achieved,
            'real_time_factor_asked': asked}


def test_a_run_is_counted_at_the_profile_s_cost_then_at_the_class_s_measured_one():
    admission = Admission(2, 0.94, 8)
    assert admission.most_at_once() == 2
    assert admission.may_start(1.0)
    admission.started('a', 1.0)
    assert admission.may_start(1.0)
    admission.started('b', 1.0)
    assert not admission.may_start(1.0)         # 1.88 + 0.94 > 2
    assert not admission.ended('a', ran(0.6))   # measured: 0.6, not starved
    assert admission.per_run() == pytest.approx(0.6)
    assert admission.may_start(1.0)             # 0.94 counted for b, + 0.6
    for cores in (0.5, 0.62, 0.64):
        admission.costs.append(cores)
    assert admission.per_run() == pytest.approx(0.62)    # the median of 4 (the upper one)
    assert admission.most_at_once() == 3 and admission.most_at_once(2.0) == 1


def test_a_submission_s_runs_count_at_what_its_own_code_costs():
    """Its releases, repeats and episodes run the same code: a run of a measured
    submission is counted at its own cost, another's at the class's median."""
    admission = Admission(2, 0.94, 8)
    admission.counted(ran(1.7), 'busy_loops')
    admission.counted(ran(0.2), 'quiet')
    admission.counted(ran(1.0), 'middle')
    assert admission.per_run('busy_loops') == pytest.approx(1.7)
    assert admission.per_run('quiet') == pytest.approx(0.2)
    assert admission.per_run('new') == pytest.approx(1.0)      # the class's median
    admission.started('busy_loops-melodic', 1.0, 'busy_loops')
    assert admission.may_start(1.0, 'quiet')       # 1.7 + 0.2 <= 2 but the teacher's 0.1
    assert not admission.may_start(1.0, 'middle')              # 1.7 + 1.0 > 2
    admission.counted(ran(0.9), 'busy_loops')                  # its dearest run counts
    assert admission.per_run('busy_loops') == pytest.approx(1.7)


def test_a_submission_whose_python_loops_without_waiting_counts_dearer_until_measured():
    """A loop that goes round without waiting keeps a core busy: such a submission,
    not yet measured, is not started beside another run it would starve."""
    admission = Admission(2, 0.7, 8)
    admission.expect_busy('spins')
    assert admission.per_run('spins') == pytest.approx(0.7 + BUSY)
    assert admission.per_run('quiet') == pytest.approx(0.7)
    admission.started('quiet', 1.0, 'quiet')
    assert not admission.may_start(1.0, 'spins')            # 0.7 + 1.5 > 2
    assert admission.may_start(1.0, 'other')
    admission.counted(ran(0.9), 'spins')                      # its own run says
    assert admission.per_run('spins') == pytest.approx(0.9)
    admission.counted(ran(0.4), 'quiet')
    assert admission.per_run('later') == pytest.approx(0.4)   # the class's median: no BUSY


def test_the_first_run_always_starts_and_as_fast_as_possible_takes_every_core():
    admission = Admission(2, 5.0, 8)
    assert admission.may_start(1.0)
    admission.started('a', 0.0)
    assert admission.running['a'] == 2.0 and not admission.may_start(0.5)
    most = Admission(64, 0.1, 2)
    most.started('a', 1.0)
    most.started('b', 1.0)
    assert not most.may_start(1.0)              # --jobs 2 is the most
    remote = Admission(None, 0.94, 100)         # a Dask scheduler's workers decide
    for label in 'abcdef':
        assert remote.may_start(1.0)
        remote.started(label, 1.0)


def test_starved_and_cost_read_a_finished_run_s_record():
    assert starved(ran(0.8, achieved=0.91)) == 0.91
    assert starved(ran(0.8, achieved=0.96)) is None
    assert starved(ran(0.8, achieved=1.85, asked=2.0)) == 1.85     # 0.925 of 2
    assert starved({'real_time_factor': 0.5, 'truth': {'sim_time': 0.0}}) is None  # never ran
    assert cost(ran(0.8)) == pytest.approx(0.8)
    assert cost(ran(0.8, sim=3.0)) is None      # too short to say
    assert cost({}) is None


class CostlyCluster(Cluster):
    """The stand-in cluster whose runs come back with measured costs: each
    label's list of facts, one per attempt (its last for later ones)."""

    def __init__(self, facts, slots=64):
        Cluster.__init__(self, slots)
        self.facts, self.keys, self.at_once = facts, [], []

    def submit(self, payload):
        self.keys.append((payload['label'], payload.get('attempt')))
        return Cluster.submit(self, payload)

    def poll_starts(self):
        Cluster.poll_starts(self)
        running = [f for f in self.futures if f.label in self.started and not f.done()]
        self.at_once.append(sorted(f.label for f in running))

    def step(self):
        for future in self.futures:
            if future.label in self.started and not future.done():
                tries = self.facts[future.label]
                attempt = sum(1 for label, _ in self.keys if label == future.label)
                future.outcome = came_back(future.name, future.label, ended_by='duration',
                                           **tries[min(attempt, len(tries)) - 1])
                return


class Progress(object):
    total = 0

    def __init__(self, cluster):
        self.cluster, self.shown, self.said = cluster, 0, []

    def show(self, runs):
        self.shown += 1
        if self.shown % 2 == 0:
            self.cluster.step()

    def line(self, text):
        self.said.append(text)


def test_runs_start_as_their_measured_cost_lets_and_a_starved_one_runs_again_alone(
        tmp_path, no_wait):
    names = ['a', 'b', 'c', 'd', 'e']
    facts = {n: [ran(0.6)] for n in names}
    facts['b'] = [ran(0.6, achieved=0.91), ran(0.6, achieved=0.99)]
    cluster = CostlyCluster(facts)
    runs = runs_of(tmp_path, names)
    admission = Admission(2, 0.94, 8)
    left = dispatch.grade(runs, cluster, Progress(cluster), copies=None, admission=admission)
    assert left == []
    # two at first (0.94 each), three once a run was measured at 0.6
    assert max(len(now) for now in cluster.at_once[:2]) == 2
    assert max(len(now) for now in cluster.at_once) == 3
    # b starved: sent again (a task of its own) after every other one ended, alone
    assert cluster.keys[-1] == ('b', 2) and [k for k in cluster.keys if k[0] == 'b'] == [
        ('b', 1), ('b', 2)]
    assert cluster.at_once[-1] in (['b'], [])
    b = next(r for r in runs if r.label == 'b')
    assert b.result['real_time_factor'] == 0.99
    assert record.notes(b.result) == ['run again: its first run was starved (0.91 of real time)']
    with open(os.path.join(b.record, 'teacher.json')) as f:
        assert json.load(f)['notes'] == [
            'run again: its first run was starved (0.91 of real time)']
    assert all(not record.notes(r.result) for r in runs if r.label != 'b')


def test_a_cheap_run_starts_beside_a_dear_one_where_the_next_in_line_would_not_fit(
        tmp_path, no_wait):
    """dear (1.6 cores) runs; mid (1.0) is next in line and does not fit beside it;
    cheap (0.3), behind it, does, and starts at once (first fit)."""
    facts = {'dear': [ran(1.6)], 'mid': [ran(1.0)], 'cheap': [ran(0.3)]}
    cluster = CostlyCluster(facts)
    runs = runs_of(tmp_path, ['dear', 'mid', 'cheap'])
    admission = Admission(2, 0.94, 8)
    for name, facts_of in facts.items():
        admission.counted(facts_of[0], name)        # measured before (a resumed grading's)
    dispatch.grade(runs, cluster, Progress(cluster), copies=None, admission=admission)
    assert cluster.keys[:2] == [('dear', 1), ('cheap', 1)]
    assert ['cheap', 'dear'] in cluster.at_once and ['dear', 'mid'] not in cluster.at_once


def test_a_run_starved_twice_is_kept_as_it_came_the_second_time(tmp_path, no_wait):
    cluster = CostlyCluster({'a': [ran(0.6, achieved=0.9), ran(0.6, achieved=0.92)]})
    runs = runs_of(tmp_path, ['a'])
    dispatch.grade(runs, cluster, Progress(cluster), copies=None,
                   admission=Admission(2, 0.94, 8))
    assert cluster.keys == [('a', 1), ('a', 2)]
    assert runs[0].result['real_time_factor'] == 0.92
    assert record.notes(runs[0].result) == [
        'run again: its first run was starved (0.90 of real time)']


def test_a_starved_run_whose_first_worker_was_lost_keeps_both_facts(tmp_path, no_wait):
    """Its first attempt's worker lost and the task done again elsewhere (Dask),
    then starved and sent again: its workers are every start's, in order, and
    its notes say both (the starved second attempt is no lost worker)."""
    cluster = CostlyCluster({'a': [ran(0.6, achieved=0.9), ran(0.6)]})
    first_poll = cluster.poll_starts

    def poll_starts():          # a worker lost: Dask started the first attempt twice
        first_poll()
        for label, workers in cluster.started.items():
            if len(workers) == 1 and not cluster.attempts.get(label):
                cluster.started[label] = ['tcp://lost:1', 'tcp://b:2']
                cluster.attempts[label] = [1, 1]
        if len(cluster.keys) == 2 and len(cluster.started['a']) == 2:
            cluster.started['a'].append('tcp://c:3')
            cluster.attempts['a'].append(2)
    cluster.attempts, cluster.poll_starts = {}, poll_starts
    runs = runs_of(tmp_path, ['a'])
    dispatch.grade(runs, cluster, Progress(cluster), copies=None,
                   admission=Admission(2, 0.94, 8))
    assert cluster.keys == [('a', 1), ('a', 2)]
    with open(os.path.join(runs[0].record, 'teacher.json')) as f:
        teacher = json.load(f)
    assert teacher['workers'] == ['tcp://lost:1', 'tcp://b:2', 'tcp://c:3']
    assert teacher['notes'] == [
        'run again: its first run was starved (0.90 of real time)',
        'run again: its worker tcp://lost:1 was lost in the middle of the run; done on '
        'tcp://b:2']

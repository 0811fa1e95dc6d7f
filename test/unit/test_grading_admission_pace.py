"""What a running run costs, read as it runs (run.cpu.Pace), told to the
teacher's side (run.tasks._watch, the cluster's queue) and counted by the
admission at once: a second run starts beside the first within a minute of
the first's start rather than when it has ended, and a submission thought
dear (a busy loop) that is not is counted at what it costs. No ROS, no
sandbox, no Dask scheduler."""
import threading

import pytest

distributed = pytest.importorskip('distributed')
from exp_assignment2.grading.run import cpu  # noqa: E402
from exp_assignment2.grading.run import dispatch  # noqa: E402
from exp_assignment2.grading.run import tasks  # noqa: E402
from exp_assignment2.grading.run.admission import BUSY, LIVE_MARGIN, Admission  # noqa: E402
from test_grading_admission import CostlyCluster, Progress, ran  # noqa: E402
from test_grading_stopping import runs_of  # noqa: E402
from test_grading_stopping import no_wait  # noqa: E402,F401 -- the fixture


def test_a_pace_is_read_from_the_warm_up_on_over_ten_simulated_s_at_least(monkeypatch):
    used = {'cpu': 0.0}
    monkeypatch.setattr(cpu, 'snapshot', lambda pids: ({'student': used['cpu']}, {}))
    pace = cpu.Pace()
    used['cpu'] = 30.0                   # the start-up: roslaunch, spawns, a build
    assert pace.look([1], 5.0, 100.0) is None          # before the warm-up: not read
    assert pace.look([1], cpu.WARM, 110.0) is None     # the base
    used['cpu'] = 34.0
    assert pace.look([1], cpu.WARM + 5, 112.0) is None     # within a look of the last
    assert pace.look([1], cpu.WARM + 5, 121.0) is None     # 5 simulated s: too few to say
    used['cpu'] = 38.0
    assert pace.look([1], cpu.WARM + 20, 131.0) == pytest.approx(8.0 / 20)
    assert pace.cost == pytest.approx(0.4)
    used['cpu'] = 20.0                   # a process ended, taking its CPU with it
    assert pace.look([1], cpu.WARM + 30, 141.0) is None     # read again from here
    used['cpu'] = 26.0
    assert pace.look([1], cpu.WARM + 45, 151.0) == pytest.approx(0.4)


def test_a_running_run_counts_at_its_pace_for_it_and_for_what_is_not_measured():
    admission = Admission(2, 0.9, 8)
    admission.expect_busy('spins')
    admission.started('spins', 1.0, 'spins')          # 0.9 + BUSY counted
    assert admission.running['spins'] == pytest.approx(0.9 + BUSY)
    assert not admission.may_start(1.0, 'quiet')      # 1.7 + 0.9 > 2
    admission.pace('spins', 0.5)                      # it does not spin much after all
    assert admission.running['spins'] == pytest.approx(0.5 * LIVE_MARGIN)
    assert admission.per_run('spins') == pytest.approx(0.5 * LIVE_MARGIN)
    assert admission.per_run('quiet') == pytest.approx(0.5 * LIVE_MARGIN)   # the class's
    assert admission.may_start(1.0, 'quiet')
    admission.started('quiet', 1.0, 'quiet')
    admission.pace('quiet', 1.2)                      # dearer than thought: counted so
    assert admission.running['quiet'] == pytest.approx(1.2 * LIVE_MARGIN)
    assert not admission.may_start(1.0, 'third')
    admission.pace('gone', 0.1)                       # a run no longer running: nothing
    for wrong in (float('nan'), float('inf'), -1.0, None, 'fast'):
        admission.pace('quiet', wrong)                # a pace that is no pace: as it was
    assert admission.running['quiet'] == pytest.approx(1.2 * LIVE_MARGIN)
    assert 'gone' not in admission.running
    admission.ended('spins', ran(0.52), 'spins')      # its end: the measured cost counts
    assert admission.per_run('spins') == pytest.approx(0.52)
    assert 'spins' not in admission.paces
    assert admission.per_run('later') == pytest.approx(0.52)    # of 0.52 and 1.32, the lower


def test_the_second_run_starts_beside_the_first_once_its_pace_is_told(tmp_path, no_wait):
    """The profile says 1.5 cores a run: without a pace, one at a time; the first's
    pace (0.4) is told while it runs, and the second starts beside it."""
    facts = {n: [ran(0.4)] for n in ('a', 'b', 'c')}

    class PacedCluster(CostlyCluster):
        told = False

        def poll_starts(self):
            CostlyCluster.poll_starts(self)
            if 'a' in self.started and not self.told:
                self.told, self.paces['a'] = True, 0.4

    cluster = PacedCluster(facts)
    dispatch.grade(runs_of(tmp_path, list(facts)), cluster, Progress(cluster), copies=None,
                   admission=Admission(2, 1.5, 8))
    assert ['a', 'b'] in cluster.at_once or ['a', 'b', 'c'] in cluster.at_once


def test_the_worker_tells_each_new_pace_once_and_its_ending_once():
    class Run(object):
        pace, state = None, 'running'
        stop_event = threading.Event()
    run, told, looks = Run(), [], []

    def stop():
        looks.append(1)
        run.pace = {1: None, 2: 0.3, 3: 0.3, 4: 0.35}.get(len(looks), 0.35)
        if len(looks) >= 5:
            run.state = 'ending' if len(looks) < 8 else 'done'
        return False
    tasks._watch(run, stop, told.append)
    assert told == [{'pace': 0.3}, {'pace': 0.35}, {'ending': True}]


def test_an_ending_run_counts_little_and_the_next_starts_as_it_ends(tmp_path, no_wait):
    admission = Admission(2, 1.5, 8)
    admission.started('a', 1.0, 'a')
    admission.pace('a', 1.6)
    assert not admission.may_start(1.0, 'b')
    admission.ending('a')
    assert admission.may_start(1.0, 'b') and 'a' not in admission.paces
    admission.ending('gone')                    # no longer running: nothing
    assert 'gone' not in admission.running

    class EndingCluster(CostlyCluster):
        def poll_starts(self):
            CostlyCluster.poll_starts(self)
            for label in self.started:
                if label not in self.told:
                    self.told.add(label)
                    self.ending.add(label)      # said at once: it is ending
    cluster = EndingCluster({n: [ran(1.6)] for n in ('a', 'b')})
    cluster.told = set()
    dispatch.grade(runs_of(tmp_path, ['a', 'b']), cluster, Progress(cluster), copies=None,
                   admission=Admission(2, 1.6, 8))
    assert ['a', 'b'] in cluster.at_once


def test_the_teacher_s_side_reads_starts_paces_and_ends_from_one_queue():
    from exp_assignment2.grading.run.cluster import Cluster as DaskCluster

    class Queue(object):
        def get(self, batch=False):
            return [{'label': 'a', 'worker': 'tcp://w:1', 'attempt': 1, 'time': 0.0},
                    {'label': 'a', 'pace': 0.42}, {'label': 'b', 'pace': 0.9},
                    {'label': 'a', 'pace': 0.44}, {'label': 'b', 'ending': True}]
    cluster = DaskCluster.__new__(DaskCluster)
    cluster.starts, cluster.started, cluster.attempts = Queue(), {}, {}
    cluster.paces, cluster.ending = {}, set()
    cluster.poll_starts()
    assert cluster.started == {'a': ['tcp://w:1']} and cluster.attempts == {'a': [1]}
    assert cluster.paces == {'a': 0.44, 'b': 0.9} and cluster.ending == {'b'}


def test_one_that_spins_is_counted_on_the_profile_s_figure_when_the_class_s_is_cheaper():
    """A real class: three runs whose camera nobody watched pulled the median to 0.36;
    a spinning submission counted at 0.36 + BUSY started beside a run of 0.71 and
    starved at 1.31 cores. It is counted at max(median, profile) + BUSY."""
    admission = Admission(2, 0.76, 8)
    admission.expect_busy('spins')
    for cores in (0.22, 0.23, 0.36, 0.78, 0.81):
        admission.costs.append(cores)
    assert admission.per_run('quiet') == pytest.approx(0.36)
    assert admission.per_run('spins') == pytest.approx(0.76 + BUSY)
    admission.started('other', 1.0, 'other')
    admission.pace('other', 0.71 / LIVE_MARGIN)
    assert not admission.may_start(1.0, 'spins')
    admission.costs[:] = [1.0, 1.1, 1.2]
    assert admission.per_run('spins') == pytest.approx(1.1 + BUSY)

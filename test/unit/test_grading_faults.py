"""A fault of the grader's with one submission is that submission's
``grader_error``, with its cause; the others are graded and the report is
written (exp_assignment2.grading.plan.planning, runner, run.dispatch, cli)."""
import argparse
import os

from exp_assignment2.grading.entry import build_deps
from exp_assignment2.grading import cli
from exp_assignment2.grading.plan import launch_nodes
from exp_assignment2.grading.plan import planning
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.entry.copies import Copies
from exp_assignment2.grading.run import dispatch
from exp_assignment2.grading.run.runner import Run, RunSettings
from exp_assignment2.grading.plan.spec import RunSpec

PACKAGE_XML = '<package format="2"><name>%s</name><version>0.0.1</version></package>'


def _class(tmp_path, names):
    folder = tmp_path / 'class'
    for name in names:
        (folder / name).mkdir(parents=True)
        (folder / name / 'package.xml').write_text(PACKAGE_XML % name)
    return folder


def test_a_fault_while_reading_one_submission_is_its_grader_error(tmp_path, monkeypatch):
    folder = _class(tmp_path, ['ann', 'bob'])
    monkeypatch.setattr(build_deps, 'available_debian', lambda: set())
    monkeypatch.setattr(build_deps, 'install', lambda names, log: None)
    monkeypatch.setattr(launch_nodes, 'provided_packages', lambda: set())
    real = planning.commands_for

    def faulty(submission, *args):
        if submission.name == 'bob':
            raise TypeError('the grader tripped')
        return real(submission, *args)
    monkeypatch.setattr(planning, 'commands_for', faulty)
    args = argparse.Namespace(submissions=str(folder), profile=None, duration=None,
                              real_time_factor=None, only=None, repeat=1, seed=1)
    said = []
    with Copies() as copies:
        specs, _, _ = planning.plan(args, str(tmp_path / 'out'), '0.1', said.append,
                                    planning.read_settings(args),
                                    planning.entries(args, said.append), copies)
    by_name = {s.name: s for s in specs}
    assert by_name['ann'].refused is None and by_name['ann'].package == 'ann'
    assert by_name['bob'].refused.startswith("the grader failed while reading the submission "
                                             "(a fault of the grader's, not the student's): "
                                             "TypeError: the grader tripped (test_grading_faults")
    assert any(line.startswith('bob: the grader failed while reading it') for line in said)


def test_a_fault_while_running_or_judging_is_the_runs_grader_error(tmp_path, monkeypatch):
    folder = _class(tmp_path, ['ann'])
    profile = profiles.load('dog')
    spec = RunSpec(name='ann', path=str(folder / 'ann'), kind='dir', profile=profile,
                   duration=10.0)
    run = Run(RunSettings(profile, str(tmp_path / 'runs')), spec)
    monkeypatch.setattr(Run, '_go', lambda self, result: 1 / 0)
    result = run.go()
    assert result['verdict'] == 'grader_error'
    assert 'ZeroDivisionError' in result['reason'] and "fault of the grader's" in result['reason']
    assert os.path.isfile(os.path.join(run.record, 'run.json'))


def test_a_rejected_submission_is_not_built_without_a_worker(tmp_path):
    profile = profiles.load('dog')
    spec = RunSpec(name='pipe', path=str(tmp_path / 'pipe'), kind='other', profile=profile,
                   duration=10.0, rejected='the submission: not a file nor a folder')
    run = Run(RunSettings(profile, str(tmp_path / 'runs')), spec)

    class NoCluster(object):
        version, paces, ending = '0', {}, set()

        def submit(self, payload):
            raise AssertionError('nothing to send')

        def poll_starts(self):
            pass

        started = {}

    class Quiet(object):
        def show(self, runs):
            pass

        def line(self, text):
            pass
    dispatch.grade([run], NoCluster(), Quiet(), None)
    assert (run.result['verdict'], run.result['reason']) == (
        'not_built', 'the submission: not a file nor a folder')


def test_a_run_that_cannot_be_sent_is_its_grader_error(tmp_path, monkeypatch):
    profile = profiles.load('dog')
    spec = RunSpec(name='ann', path=str(tmp_path / 'gone'), kind='dir', profile=profile,
                   duration=10.0)
    run = Run(RunSettings(profile, str(tmp_path / 'runs')), spec)
    monkeypatch.setattr(dispatch, 'payload', lambda run, version, copies: {}['data'])

    class NoCluster(object):
        version, started, paces, ending = '0', {}, {}, set()

        def poll_starts(self):
            pass

    class Quiet(object):
        def show(self, runs):
            pass
    dispatch.grade([run], NoCluster(), Quiet(), None)
    assert run.result['verdict'] == 'grader_error'
    assert run.result['reason'].startswith('the grader could not send it to a worker')


def test_grade_dot_in_a_package_reports_beside_it(tmp_path, monkeypatch):
    package = tmp_path / 'my_dog'
    package.mkdir()
    monkeypatch.chdir(str(package))
    assert cli.default_out('.') == str(tmp_path / 'my_dog-grading-report')
    monkeypatch.chdir(str(tmp_path))
    assert cli.default_out('my_dog') == str(tmp_path / 'grading-report')

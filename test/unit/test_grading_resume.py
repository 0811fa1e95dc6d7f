"""A grading started again keeps what finished (exp_assignment2.grading.run.resume):
a run's record is whole or absent whenever the grader is killed, a record
is kept only when its run is of the same plan (its RunSpec's and its
submission's digests), and the terminal says why each other runs again.
No ROS, no sandbox."""
import json
import os
import shutil
import subprocess

import pytest

from exp_assignment2.grading import record
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.entry.copies import Copies
from exp_assignment2.grading.plan.spec import RunSpec
from exp_assignment2.grading.run import resume as resume_
from exp_assignment2.grading.run import sandbox, tasks
from exp_assignment2.grading.run.runner import Run, RunSettings


class Killed(Exception):
    """What a SIGKILL would be, at one moment of a write."""


def _package(folder, text='print(1)'):
    os.makedirs(os.path.join(folder, 'scripts'), exist_ok=True)
    with open(os.path.join(folder, 'package.xml'), 'w') as f:
        f.write('<package><name>ann</name></package>')
    with open(os.path.join(folder, 'scripts', 'dog.py'), 'w') as f:
        f.write(text)


def _run(tmp_path, duration=20.0, **more):
    profile = profiles.load('dog')
    spec = RunSpec(name='ann', path=str(tmp_path / 'class' / 'ann'), kind='dir', label='ann',
                   profile=profile, duration=duration, hidden=[str(tmp_path / 'x')], **more)
    return Run(RunSettings(profile, str(tmp_path / 'report' / 'runs')), spec)


def _worker_record(tmp_path, verdict='passed'):
    """A run directory as a worker sends it back: its logs, frames, record."""
    worker = tmp_path / 'worker'
    shutil.rmtree(str(worker), ignore_errors=True)
    (worker / 'work' / 'logs').mkdir(parents=True)
    (worker / 'work' / 'logs' / 'command-0.log').write_text('started\n')
    (worker / 'record' / 'frames').mkdir(parents=True)
    (worker / 'record' / 'frames' / 'camera_00001.00.jpg').write_bytes(b'\xff\xd8')
    (worker / 'record' / 'events.jsonl').write_text('{"event": "built", "rc": 0}\n')
    record.write(str(worker / 'record'), record.RunRecord.new(
        'ann', 'ann', 1, verdict=verdict, run_id='a' * 32, events=[{'event': 'built'}],
        build={'rc': 0}))
    return tasks.pack_run(str(worker))[0]


def test_the_record_is_written_last_and_taken_away_first(tmp_path, monkeypatch):
    where = str(tmp_path / 'record')
    real = record._put

    def killed_at_run_json(path, text):
        if path.endswith(record.NAME):
            raise Killed()
        real(path, text)
    monkeypatch.setattr(record, '_put', killed_at_run_json)
    with pytest.raises(Killed):
        record.write(where, record.RunRecord.new('ann', 'ann', 1, verdict='passed',
                                                 teacher={'workers': ['w']}))
    # the teacher's part was written, the record not: the run is not finished
    assert os.path.exists(os.path.join(where, record.TEACHER_NAME))
    assert record.load(where) is None
    monkeypatch.setattr(record, '_put', real)
    record.write(where, record.RunRecord.new('ann', 'ann', 1, verdict='passed'))
    record.unfinish(where)
    assert os.listdir(where) == []


def test_a_new_attempt_killed_over_a_finished_run_leaves_no_record(tmp_path, monkeypatch):
    """The teacher's side unpacks a run that came back over the directory of
    an earlier one: killed half way, the earlier record is gone (not left
    beside the new attempt's half of the files)."""
    from exp_assignment2.grading.run import cluster
    run = _run(tmp_path)
    data = _worker_record(tmp_path)
    cluster.unpack_result({'archive': data}, run, {})
    assert record.load(run.record)['run_id'] == 'a' * 32
    copied = []

    def killed_after_one_file(src, out):
        if copied:
            raise Killed()
        copied.append(out)
        out.write(src.read())
    monkeypatch.setattr(tasks.shutil, 'copyfileobj', killed_after_one_file)
    with pytest.raises(Killed):
        cluster.unpack_result({'archive': data}, run, {})
    assert record.load(run.record) is None
    assert resume_.why_again(run.dir, None, {}) == resume_.NOT_FINISHED


def test_a_record_from_the_worker_is_kept_byte_for_byte_and_checked(tmp_path):
    with pytest.raises(ValueError, match='not a run record'):
        record.write(str(tmp_path), b'{"name": "ann", "who": 1}')
    with pytest.raises(ValueError, match='not a run record'):
        record.write(str(tmp_path), b'not json')
    assert not (tmp_path / record.NAME).exists()


def test_the_plan_leaves_out_where_this_grading_put_its_files(tmp_path):
    one, two = _run(tmp_path), _run(tmp_path)
    two.spec.hidden, two.spec.path = ['/elsewhere'], '/moved/ann'
    two.spec.notes = ['launch/a.launch: cannot be read: /tmp/scratch-2/0/src/a.launch']
    one.spec.notes = ['launch/a.launch: cannot be read: /tmp/scratch-1/0/src/a.launch']
    assert resume_.spec_fields(one.spec, '/tmp/scratch-1') == \
        resume_.spec_fields(two.spec, '/tmp/scratch-2')
    assert 'hidden' not in resume_.spec_fields(one.spec)


def _grading(tmp_path, copies, run):
    plan = resume_.Resume(str(tmp_path / 'report' / 'runs'), copies, log=lambda line: None)
    return plan, plan.keep(run)


def test_a_finished_run_of_the_same_plan_is_kept_and_others_say_why(tmp_path):
    from exp_assignment2.grading.run import cluster
    _package(str(tmp_path / 'class' / 'ann'))
    with Copies() as copies:
        run = _run(tmp_path)
        plan, kept = _grading(tmp_path, copies, run)
        assert kept is None and plan.again == [('ann', resume_.NEW)] and plan.lines() == []
        cluster.unpack_result({'archive': _worker_record(tmp_path)}, run, {})
        assert record.load(run.record)['teacher']['planned'] == run.planned
        plan, kept = _grading(tmp_path, copies, _run(tmp_path))
        assert kept['run_id'] == 'a' * 32 and plan.kept == ['ann']
        assert plan.lines() == ['resuming: 1 run kept, 0 to run']
        # another duration: run again, and the terminal says so
        plan, kept = _grading(tmp_path, copies, _run(tmp_path, duration=30.0))
        assert kept is None and plan.lines() == [
            'resuming: 0 runs kept, 1 to run (1 changed)',
            '  ann: run again: planned otherwise: duration: 20.0 then, 30.0 now']
        assert record.load(run.record) is None       # taken away while it runs again
    cluster.unpack_result({'archive': _worker_record(tmp_path)}, run, {})
    # the submission's files changed (a new copy of the class)
    _package(str(tmp_path / 'class' / 'ann'), 'print(2)')
    with Copies() as copies:
        plan, kept = _grading(tmp_path, copies, _run(tmp_path))
        assert kept is None and plan.again == [('ann', "the submission's files changed since")]


def test_what_is_not_finished_or_not_the_students_runs_again(tmp_path):
    run_dir = str(tmp_path / 'ann')
    planned = {'spec': 's', 'content': 'c', 'spec_fields': {}}
    mine = {'teacher': {'planned': planned}, 'events': [{'event': 'built'}],
            'build': {'rc': 0}}
    os.makedirs(os.path.join(run_dir, 'record'))
    assert resume_.why_again(run_dir, dict(mine, verdict='passed'), planned) == \
        'its directory is not whole'      # its events and logs are not there
    cut = dict(mine, verdict='passed', teacher=dict(mine['teacher'], cut=[
        'record/events.jsonl (9 bytes): over the 64 MB a run sends back',
        'work/logs/build.log (9 bytes): over the 64 MB a run sends back']))
    assert resume_.why_again(run_dir, cut, planned) is None     # not sent back: not missing
    open(os.path.join(run_dir, 'record', 'events.jsonl'), 'w').close()
    os.makedirs(os.path.join(run_dir, 'work', 'logs'))
    assert resume_.why_again(run_dir, dict(mine, verdict='passed'), planned) is None
    assert resume_.why_again(run_dir, dict(mine, verdict='passed', ended_by='cancelled'),
                             planned) == resume_.NOT_FINISHED
    assert resume_.why_again(run_dir, dict(mine, verdict='grader_error', reason='lost'),
                             planned) == 'a grader error (lost): graded again'
    assert resume_.why_again(run_dir, {'verdict': 'passed'}, planned) == \
        'recorded by a grader that kept no plan of it'


def test_runs_of_an_earlier_plan_of_a_submission_graded_now_are_taken_away(tmp_path):
    runs_dir = tmp_path / 'report' / 'runs'
    for label, name in (('ann-r1', 'ann'), ('ann-r2', 'ann'), ('ann', 'ann'), ('ben', 'ben')):
        record.write(str(runs_dir / label / 'record'), record.RunRecord.new(name, label, 1))
    with Copies() as copies:
        plan = resume_.Resume(str(runs_dir), copies)
        assert plan.drop_others([_run(tmp_path)]) == ['ann-r1', 'ann-r2']
    assert sorted(os.listdir(str(runs_dir))) == ['ann', 'ben']      # ben: not graded now


def test_a_stale_control_group_is_removed_and_a_live_ones_kept(tmp_path):
    dead = subprocess.Popen(['true'])
    dead.wait()
    for pid in (dead.pid, os.getpid()):
        (tmp_path / ('exp2-grade-dog-e1-%d-1234' % pid)).mkdir()
    (tmp_path / 'someone-else-1').mkdir()
    assert sandbox.remove_stale_groups(str(tmp_path)) == ['exp2-grade-dog-e1-%d-1234'
                                                          % dead.pid]
    assert sorted(os.listdir(str(tmp_path))) == ['exp2-grade-dog-e1-%d-1234' % os.getpid(),
                                                 'someone-else-1']


def test_the_report_says_a_grading_was_resumed_or_stopped(tmp_path):
    from exp_assignment2.grading.report import resumed
    resumed.write(str(tmp_path), {'kept': ['ann'], 'again': [['ben', 'not finished'],
                                                             ['cat', 'planned otherwise: x']],
                                  'stopped': ['dan'], 'resumed': True, 'runs': 4})
    text = ''.join(resumed.paragraph(str(tmp_path)))
    assert 'resumed an earlier one: 1 run kept' in text and '2 run then' in text
    assert '<li>ben: not finished</li><li>cat: planned otherwise: x</li>' in text
    assert 'Stopped before its end' in text and '1 run not run (dan)' in text
    assert json.loads((tmp_path / 'resume.json').read_text())['kept'] == ['ann']


def test_the_scratch_of_a_killed_grader_is_removed_by_the_next(tmp_path):
    from exp_assignment2.grading import scratch
    dead = subprocess.Popen(['true'])
    dead.wait()
    (tmp_path / ('exp2-grade-%d-abc_12' % dead.pid) / 'runs').mkdir(parents=True)
    (tmp_path / ('exp2-teacher-%d-x9' % dead.pid)).mkdir()
    (tmp_path / 'exp2-grade-8vuqbibf').mkdir()        # an older grader's: not told whose
    mine = scratch.make('grade', str(tmp_path))
    assert os.path.basename(mine).startswith('exp2-grade-%d-' % os.getpid())
    assert sorted(os.listdir(str(tmp_path))) == sorted([os.path.basename(mine),
                                                        'exp2-grade-8vuqbibf'])

"""A run travels between machines as archives (exp_assignment2.grading.run.tasks)."""
import io
import os
import tarfile

import pytest

from exp_assignment2.grading.entry.copies import Copies
from exp_assignment2.grading.run import tasks
from exp_assignment2.grading.entry.submissions import Submission, SubmissionError


def test_a_run_directory_comes_back_bounded(tmp_path):
    run = tmp_path / 'run'
    (run / 'record' / 'frames').mkdir(parents=True)
    (run / 'record' / 'run.json').write_text('{"verdict": "passed"}')
    (run / 'record' / 'frames' / 'robot_camera1_00001.00.jpg').write_bytes(b'\xff\xd8jpeg')
    (run / 'work' / 'logs').mkdir(parents=True)
    (run / 'work' / 'logs' / 'command-0.log').write_bytes(b'a' * (9 * 1024 * 1024))
    (run / 'work' / 'src').mkdir()
    (run / 'work' / 'src' / 'secret.py').write_text('not sent back')
    data, cut = tasks.pack_run(str(run))
    assert cut == ['work/logs/command-0.log: %d bytes, its middle cut' % (9 * 1024 * 1024)]
    back = tmp_path / 'back'
    # the record comes back as its bytes, for the teacher's side to write last
    assert tasks.unpack_run(data, str(back)) == b'{"verdict": "passed"}'
    assert not (back / 'record' / 'run.json').exists()
    assert (back / 'record' / 'frames' / 'robot_camera1_00001.00.jpg').exists()
    log = (back / 'work' / 'logs' / 'command-0.log').read_bytes()
    assert len(log) < 9 * 1024 * 1024 and b'[... cut by the grader ...]' in log
    assert not (back / 'work' / 'src').exists()
    small, cut = tasks.pack_run(str(run), limit=1024)
    assert len(cut) == 1 and 'over the 0 MB a run sends back' in cut[0]
    # the run's record is sent whole, as its worker wrote it, whatever its size
    big = '{"notes": ["%s"]}' % ('x' * (tasks.FILE_LIMIT + 10))
    (run / 'record' / 'run.json').write_text(big)
    data, cut = tasks.pack_run(str(run), limit=1024)
    assert tasks.unpack_run(data, str(back)) == big.encode()
    assert not any('run.json' in c for c in cut)


def test_a_directory_submission_travels_without_links_out(tmp_path):
    package = tmp_path / 'ann'
    (package / 'scripts').mkdir(parents=True)
    (package / 'package.xml').write_text('<package><name>ann</name></package>')
    (package / 'scripts' / 'dog.py').write_text('print(1)')
    os.symlink('dog.py', str(package / 'scripts' / 'alias.py'))       # inside: kept
    os.symlink('/etc', str(package / 'etc'))                          # out: left out
    with Copies() as copies:
        kind, data = tasks.pack_submission(Submission('ann', str(package), 'dir'), copies)
    assert kind == 'tar' and data[:2] == b'\x1f\x8b'
    with tarfile.open(fileobj=io.BytesIO(data)) as archive:
        members = {m.name: m for m in archive}
    assert members['ann/scripts/alias.py'].issym()
    assert members['ann/scripts/alias.py'].linkname == 'dog.py'
    assert 'ann/etc' not in members


def test_a_worker_of_another_version_refuses(monkeypatch):
    monkeypatch.setenv(tasks.VERSION_ENV, '9.9.9')
    with pytest.raises(tasks.VersionMismatch, match='this worker has exp_assignment2 9.9.9, '
                                                    'the teacher 0.1.0'):
        tasks.run_task({'version': '0.1.0'})


def test_a_run_that_came_back_keeps_its_workers_record(tmp_path):
    """The teacher's side unpacks what the worker sent and adds its own part
    (the workers, a retry's note, what was cut) beside the worker's run.json,
    which it never writes again; a run lost or refused is decided by the
    verdict table on that fact."""
    from exp_assignment2.grading import record
    from exp_assignment2.grading.plan import profiles
    from exp_assignment2.grading.plan.spec import RunSpec
    from exp_assignment2.grading.run import cluster
    from exp_assignment2.grading.run.runner import Run, RunSettings
    worker = tmp_path / 'worker'
    record.write(str(worker / 'record'), record.RunRecord.new('ann', 'ann', 1,
                                                              verdict='passed', notes=['n']))
    sent = (worker / 'record' / 'run.json').read_bytes()
    data, _ = tasks.pack_run(str(worker))
    profile = profiles.load('dog')
    run = Run(RunSettings(profile, str(tmp_path / 'runs')),
              RunSpec(name='ann', path=str(tmp_path), kind='dir', profile=profile))
    got = cluster.unpack_result({'archive': data, 'cut': ['logs/x: cut']}, run,
                                {'ann': ['tcp://a:1', 'tcp://b:2']})
    assert (tmp_path / 'runs' / 'ann' / 'record' / 'run.json').read_bytes() == sent
    assert got['verdict'] == 'passed' and got['teacher'] == {
        'workers': ['tcp://a:1', 'tcp://b:2'], 'cut': ['logs/x: cut'],
        'notes': ['run again: its worker tcp://a:1 was lost in the middle of the run; done '
                  'on tcp://b:2']}
    assert run.result == got and run.state == 'done'
    lost = cluster.lost_result(run, RuntimeError('Attempted to run task on 4 workers\nmore'),
                               {'ann': ['w1', 'w2', 'w3', 'w4']})
    assert (lost['verdict'], lost['reason'], lost['ended_by']) == (
        'grader_error', 'the grader lost this run: Attempted to run task on 4 workers',
        'not_run')
    assert record.load(run.record) == lost and lost['teacher'] == {
        'workers': ['w1', 'w2', 'w3', 'w4']}
    with pytest.raises(ValueError, match='no record'):
        cluster.unpack_result({'archive': tasks.pack_run(str(tmp_path / 'none'))[0]}, run, {})

"""A run travels between machines as archives (exp_assignment2.grading.run.tasks)."""
import io
import os
import tarfile

import pytest

from exp_assignment2.grading.run import tasks
from exp_assignment2.grading.plan.submissions import Submission, SubmissionError


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
    tasks.unpack_run(data, str(back))
    assert (back / 'record' / 'run.json').read_text() == '{"verdict": "passed"}'
    assert (back / 'record' / 'frames' / 'robot_camera1_00001.00.jpg').exists()
    log = (back / 'work' / 'logs' / 'command-0.log').read_bytes()
    assert len(log) < 9 * 1024 * 1024 and b'[... cut by the grader ...]' in log
    assert not (back / 'work' / 'src').exists()
    small, cut = tasks.pack_run(str(run), limit=1024)
    assert len(cut) == 1 and 'over the 0 MB a run sends back' in cut[0]


def test_a_directory_submission_travels_without_links_out(tmp_path):
    package = tmp_path / 'ann'
    (package / 'scripts').mkdir(parents=True)
    (package / 'package.xml').write_text('<package><name>ann</name></package>')
    (package / 'scripts' / 'dog.py').write_text('print(1)')
    os.symlink('dog.py', str(package / 'scripts' / 'alias.py'))       # inside: kept
    os.symlink('/etc', str(package / 'etc'))                          # out: left out
    kind, data = tasks.pack_submission(Submission('ann', str(package), 'dir'))
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

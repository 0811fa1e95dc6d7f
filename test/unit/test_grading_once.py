"""One grading's teacher's side does each thing once (issue 50): grading.yaml
read once, the folder discovered once, each submission copied once (for the
planning, the archive each worker gets, the run again in another release and
the similarity report; a git repository's commit chosen once and its tree
exported once), the copies removed, and index.html written once with its
similarity column. The runs themselves are a stand-in cluster's: no ROS, no
sandbox."""
import io
import json
import os
import tarfile
import tempfile
import zipfile

import pytest

pytest.importorskip('copydetect')
distributed = pytest.importorskip('distributed')
from exp_assignment2.grading import cli  # noqa: E402
from exp_assignment2.grading.entry import build_deps  # noqa: E402
from exp_assignment2.grading.plan import launch_nodes, planning  # noqa: E402
from exp_assignment2.grading.entry import copies, git_entries, unpacking  # noqa: E402
from exp_assignment2.grading.report import index  # noqa: E402
from exp_assignment2.grading.run import tasks  # noqa: E402
from git_helpers import make_repository  # noqa: E402

CODE = 'import rospy\n\n' + ''.join('def f%d(a):\n    return a * K + %d\n' % (i, i)
                                     for i in range(30))
PACKAGE_XML = '<package format="2"><name>%s</name><version>0.0.1</version></package>'


class Done(object):
    """A run its worker did at once: its record (failed_checks, so that it is
    run again in the next ROS release) in the archive a worker sends back."""

    def __init__(self, payload):
        self.payload = payload

    def done(self):
        return True

    def result(self):
        run = tempfile.mkdtemp()
        os.makedirs(os.path.join(run, 'record'))
        label = self.payload['label']
        with open(os.path.join(run, 'record', 'run.json'), 'w') as f:
            json.dump({'name': self.payload['spec']['name'], 'label': label, 'seed': 1,
                       'verdict': 'failed_checks', 'reason': 'x', 'checks': []}, f)
        data, cut = tasks.pack_run(run)
        return {'archive': data, 'cut': cut}


class Cluster(object):
    version, started = '0.1.0', {}
    sent = []
    payloads = {}
    paces, ending = {}, set()

    def __init__(self, *args, **kwargs):
        pass

    def submit(self, payload):
        self.sent.append(payload['label'])
        self.payloads[payload['label']] = payload
        return Done(payload)

    def poll_starts(self):
        pass

    def worker_count(self):
        return 1

    def cancel(self, futures):
        pass

    def close(self):
        pass


def _class(folder):
    for name in ('ann', 'ben', 'cat'):
        os.makedirs(os.path.join(folder, name, 'scripts'))
        with open(os.path.join(folder, name, 'package.xml'), 'w') as f:
            f.write(PACKAGE_XML % name)
        with open(os.path.join(folder, name, 'scripts', 'dog.py'), 'w') as f:
            f.write(CODE.replace('K', str(len(name))))
    with zipfile.ZipFile(os.path.join(folder, 'dan.zip'), 'w') as archive:
        archive.writestr('dan/package.xml', PACKAGE_XML % 'dan')
        archive.writestr('dan/scripts/dog.py', CODE.replace('K', '7'))
    with open(os.path.join(folder, 'grading.yaml'), 'w') as f:
        f.write('duration: 20\n')
    # a git repository, graded at its last commit before the deadline (the second)
    return make_repository(os.path.join(folder, 'eve'), [
        '2025-03-01T10:00:00+01:00', '2025-03-02T10:00:00+01:00', '2025-03-03T10:00:00+01:00'],
        package='eve')


def test_a_grading_reads_discovers_copies_and_writes_its_index_once(tmp_path, monkeypatch):
    folder, out = str(tmp_path / 'class'), str(tmp_path / 'report')
    hashes = _class(folder)
    counts = {'grading.yaml read': 0, 'folder discovered': 0, 'copies made': 0,
              'index written': 0, 'commits chosen': 0, 'commits exported': 0}

    def counting(module, name, key):
        real = getattr(module, name)

        def counted(*args, **kwargs):
            counts[key] += 1
            return real(*args, **kwargs)
        monkeypatch.setattr(module, name, counted)
    counting(planning, 'read_teacher_file', 'grading.yaml read')
    counting(planning, 'discover', 'folder discovered')
    counting(index, '_write_index', 'index written')
    counting(git_entries, 'choose', 'commits chosen')
    counting(git_entries, 'export', 'commits exported')
    made = unpacking.Unpacked.__init__       # every copy or unpacking makes one

    def unpacked(self, dest):
        counts['copies made'] += 1
        made(self, dest)
    monkeypatch.setattr(unpacking.Unpacked, '__init__', unpacked)
    scratch = []
    real_copies = copies.Copies.__init__

    def noted(self, *args):
        real_copies(self, *args)
        scratch.append(self.scratch)
    monkeypatch.setattr(copies.Copies, '__init__', noted)
    monkeypatch.setattr(build_deps, 'available_debian', lambda: set())
    monkeypatch.setattr(build_deps, 'install', lambda names, log: None)
    monkeypatch.setattr(launch_nodes, 'provided_packages', lambda: set())
    monkeypatch.setattr(distributed, 'wait', lambda *args, **kwargs: None)
    monkeypatch.setattr(cli, 'Cluster', Cluster)
    monkeypatch.setattr(Cluster, 'sent', [])
    monkeypatch.setattr(Cluster, 'payloads', {})
    assert cli.main([folder, '--out', out, '--jobs', '1',
                     '--deadline', '2025-03-02T12:00:00+01:00']) == 0
    # each ran twice (its checks failed: run again in the next release), packed twice
    assert len(Cluster.sent) == 10
    # before issue 50: 3 reads, 2 discoveries, 14 copies (planning 4, packing 6, similarity 4)
    # and the index written, then patched; the git repository's commit chosen once (by the
    # planning) and exported once (its copy), not again to pack it or to compare it
    assert counts == {'grading.yaml read': 1, 'folder discovered': 1, 'copies made': 5,
                      'index written': 1, 'commits chosen': 1, 'commits exported': 1}
    sent = Cluster.payloads['eve']
    assert sent['spec']['git']['commit'] == hashes[1]      # its record says so (run.json)
    with tarfile.open(fileobj=io.BytesIO(sent['data'])) as archive:
        node = next(m for m in archive.getmembers() if m.name.endswith('scripts/node.py'))
        assert b'VERSION = 2\n' in archive.extractfile(node).read()
    shared = json.load(open(os.path.join(out, 'similarity.json')))
    assert 'eve' in {s['name'] for s in shared['submissions']}
    assert len(scratch) == 1 and not os.path.exists(scratch[0])
    text = open(os.path.join(out, 'index.html')).read()
    assert 'href="similarity.html"' in text and '>most shared with</th>' in text
    # five, no template: too few to tell the course's code from a copy, so no figure
    assert shared['too_small'] and text.count('<td data-key="0">—</td>') == 5

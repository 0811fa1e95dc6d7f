"""``bash tools/run grade CLASS --template DIR --similarity-only`` end to end,
as a teacher runs it (issue 42): nothing built or run, the disguised copy on
top of similarity.json, the folder unchanged. No simulation: seconds."""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import similarity_fixtures  # noqa: E402


def test_similarity_only_through_tools_run(tmp_path):
    template, folder = similarity_fixtures.make_class(str(tmp_path))
    before = sorted(os.walk(folder))
    out = str(tmp_path / 'report')
    proc = subprocess.run(['bash', os.path.join(REPO, 'tools', 'run'), 'grade', folder,
                           '--template', template, '--similarity-only', '--out', out],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-2000:]
    assert 'most: copier and original' in proc.stdout
    with open(os.path.join(out, 'similarity.json')) as f:
        data = json.load(f)
    assert (data['pairs'][0]['a'], data['pairs'][0]['b']) == ('copier', 'original')
    assert not os.path.exists(os.path.join(out, 'runs'))     # nothing was run
    assert sorted(os.walk(folder)) == before

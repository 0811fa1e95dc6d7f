"""A copy reads as a copy (issue 52): a pair's share is measured on the code
that is theirs, what the whole class shares left out of both sides; only the
packages graded count; earlier years' submissions are compared with the class
(grading/similarity/pairs.py, graded.py, step.py; no ROS, nothing run)."""
import json
import os
import random
import shutil
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..'))
pytest.importorskip('copydetect')
import similarity_fixtures  # noqa: E402
from exp_assignment2.grading import cli  # noqa: E402
from exp_assignment2.grading.plan import profiles  # noqa: E402
from exp_assignment2.grading.entry.copies import Copies  # noqa: E402
from exp_assignment2.grading.entry.submissions import discover  # noqa: E402
from exp_assignment2.grading.similarity import fingerprints as similarity  # noqa: E402
from exp_assignment2.grading.similarity import pairs  # noqa: E402
from exp_assignment2.grading.similarity import step  # noqa: E402

DOG = profiles.load('dog')


@pytest.fixture(scope='module')
def made(tmp_path_factory):
    """The tests' class, with a byte-identical copy of student_1 and a renamed
    copy of student_2 (its package renamed, its node disguised)."""
    root = str(tmp_path_factory.mktemp('share'))
    template, folder = similarity_fixtures.make_class(root)
    shutil.copytree(os.path.join(folder, 'student_1'), os.path.join(folder, 'twin'))
    similarity_fixtures.renamed_copy(os.path.join(folder, 'student_2'),
                                     os.path.join(folder, 'renamed'), 'my_dog',
                                     random.Random(5))
    return root, template, folder


def compared(folder, templates=()):
    subs = [similarity.Submission.read(n, os.path.join(folder, n))
            for n in sorted(os.listdir(folder))]
    return pairs.compare(subs, similarity.template_hashes(list(templates)))


def stepped(folder, out, **settings):
    """The similarity step on the folder discovered once, read from its copies."""
    with Copies() as copies:
        return step.run(discover(folder)[0], out, [], copies, log=lambda _: None, **settings)


def by_pair(result):
    return {(p.a, p.b): p for p in result.pairs}


@pytest.mark.parametrize('with_template', [True, False])
def test_copies_read_as_copies_with_or_without_the_template(made, with_template):
    _, template, folder = made
    found = by_pair(compared(folder, [template] if with_template else []))
    twins = found[('student_1', 'twin')]
    assert twins.identical and twins.share == 1.0 and twins.sizes[0] > 0
    assert found[('copier', 'original')].share >= 0.7        # the line-for-line copy
    assert not found[('copier', 'original')].identical
    assert found[('renamed', 'student_2')].share >= 0.7      # renamed package and names
    others = [p.share for k, p in found.items() if k not in {
        ('student_1', 'twin'), ('copier', 'original'), ('renamed', 'student_2')}]
    assert max(others) < 0.25                                # the class's noise


def test_a_ring_of_identical_copies_is_not_base_code(tmp_path):
    """Four byte-identical copies in a class of eight: more than the base
    limit (3) carry their code, but identical ones count once."""
    template, folder = similarity_fixtures.make_class(str(tmp_path), count=5)
    for number in range(3):
        shutil.copytree(os.path.join(folder, 'student_1'), os.path.join(folder, 'ring_%d' % number))
    result = compared(folder)
    assert result.base_limit == 3
    ring = [p for p in result.pairs if p.identical]
    assert len(ring) == 6 and all(p.share == 1.0 for p in ring)     # 4 choose 2


def test_a_tiny_own_code_does_not_read_100_percent():
    """Two submissions that share one line of their own, and have little else."""
    line = 'def f(speed, angle):\n    return speed * 31.5 + angle / 7.25 - 12\n'
    rng = random.Random(1)
    a = similarity.Submission('a', {'a.py': similarity.fingerprint(
        line + similarity_fixtures.independent_code(rng, 1, 2), 'a.py', 'python')}, 'x')
    b = similarity.Submission('b', {'b.py': similarity.fingerprint(
        line + similarity_fixtures.independent_code(rng, 1, 2), 'b.py', 'python')}, 'y')
    result = pairs.compare([a, b])
    assert result.pairs and result.pairs[0].share < 0.5 and max(result.pairs[0].sizes) < 400


def _repository(root, name, rng, vendored):
    """A course repository: the graded package (code of its own) and, with
    ``vendored``, the next assignment's public exploration package."""
    similarity_fixtures.make_template(os.path.join(root, name, 'exp_assignment2'))
    similarity_fixtures._write(os.path.join(root, name, 'exp_assignment2'), 'scripts/brain.py',
                               similarity_fixtures.independent_code(rng))
    if vendored:
        similarity_fixtures.vendor(os.path.join(root, name))


def test_a_vendored_package_nothing_graded_uses_is_nobodys_copy(tmp_path):
    folder = str(tmp_path / 'class')
    rng = random.Random(11)
    for number in range(5):
        _repository(folder, 'repo_%d' % number, rng, vendored=number < 2)
    whole = by_pair(stepped(folder, str(tmp_path / 'whole')))
    assert whole[('repo_0', 'repo_1')].share > 0.3         # every file read: it shows
    graded = stepped(folder, str(tmp_path / 'out'), settings={'profile': DOG, 'teacher': {}})
    assert ('repo_0', 'repo_1') not in by_pair(graded) or \
        by_pair(graded)[('repo_0', 'repo_1')].share < 0.25
    files = {s.name: sorted(s.files) for s in graded.submissions}
    assert files['repo_0'] and all(f.startswith('exp_assignment2/') for f in files['repo_0'])


def test_the_packages_a_grading_built_are_those_compared(tmp_path):
    folder = str(tmp_path / 'class')
    rng = random.Random(12)
    for number in range(3):
        _repository(folder, 'repo_%d' % number, rng, vendored=True)
    runs = tmp_path / 'report' / 'runs'
    for number in range(3):     # records of a grading: the run built exp_assignment2 alone
        record = runs / ('repo_%d' % number) / 'record'
        record.mkdir(parents=True)
        (record / 'run.json').write_text(json.dumps({
            'name': 'repo_%d' % number, 'label': 'repo_%d' % number, 'verdict': 'passed',
            'packages': [{'name': 'exp_assignment2', 'rel': 'exp_assignment2', 'built': True},
                         {'name': 'explore_lite', 'rel': 'explore_lite', 'built': False}]}))
    result = stepped(folder, str(tmp_path / 'report'), settings={'runs_dir': str(runs)})
    assert all(rel.startswith('exp_assignment2/') for s in result.submissions for rel in s.files)


def test_earlier_years_are_compared_with_the_class_not_among_themselves(made, tmp_path):
    root, template, folder = made
    old = str(tmp_path / 'year2024')
    shutil.copytree(os.path.join(folder, 'original'), os.path.join(old, 'alice'))
    shutil.copytree(os.path.join(folder, 'original'), os.path.join(old, 'alice_twin'))
    out = str(tmp_path / 'report')
    assert cli.main([folder, '--template', template, '--similarity-only', '--out', out,
                     '--reference', old]) == 0
    data = json.load(open(os.path.join(out, 'similarity.json')))
    found = {(p['a'], p['b']): p for p in data['pairs']}
    assert found[('original', 'year2024/alice')]['identical']
    assert found[('copier', 'year2024/alice')]['share'] >= 0.7
    assert found[('copier', 'year2024/alice')]['reference']
    assert ('year2024/alice', 'year2024/alice_twin') not in found
    names = {s['name']: s for s in data['submissions']}
    assert names['year2024/alice']['reference'] and not names['copier']['reference']
    page = open(os.path.join(out, 'similarity.html')).read()
    assert 'year2024/alice (earlier year)' in page and 'identical' in page
    assert cli.main([folder, '--similarity-only', '--out', out, '--reference',
                     str(tmp_path / 'nope')]) == 2

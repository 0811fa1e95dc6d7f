"""The similarity report (issue 42), no ROS, no simulation: a disguised copy
is the top pair far above the rest; the template and a course file most
students carry flag nobody; the page escapes student text and opens in a
headless browser with its image."""
import json
import os
import random
import shutil
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..'))
sys.path.insert(0, os.path.join(HERE, '..', '..', 'src'))
pytest.importorskip('copydetect')
import similarity_fixtures  # noqa: E402
from exp_assignment2.grading import options
from exp_assignment2.grading import cli
from exp_assignment2.grading import record
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.report import index as report
from exp_assignment2.grading.similarity import fingerprints as similarity
from exp_assignment2.grading.similarity import pairs
from exp_assignment2.grading.similarity import page as similarity_report  # noqa: E402


@pytest.fixture(scope='module')
def made(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('similar'))
    template, folder = similarity_fixtures.make_class(root)
    return root, template, folder


def _read(folder):
    return [similarity.Submission.read(n, os.path.join(folder, n))
            for n in sorted(os.listdir(folder))]


def test_disguise_changes_the_text_not_the_tokens():
    rng = random.Random(3)
    text = similarity_fixtures.independent_code(rng)
    hidden = similarity_fixtures.disguise(text, rng)
    assert hidden.count('def my_') == text.count('def ')       # every function renamed
    assert '\n  my_' in hidden and '\n    return' not in hidden   # two spaces a level
    assert [line for line in hidden.split('\n') if line.startswith('def ')] != \
        [line for line in text.split('\n') if line.startswith('def ')]
    a = similarity.fingerprint(text, 'a.py', 'python')
    b = similarity.fingerprint(hidden, 'b.py', 'python')
    assert len(a.hashes & b.hashes) > 0.8 * len(a.hashes)


def test_the_copied_pair_is_top_far_above_the_rest(made):
    _, template, folder = made
    result = pairs.compare(_read(folder), similarity.template_hashes([template]))
    share, _, a, b, identical, _ = result.pairs[0]
    assert (a, b) == ('copier', 'original') and not identical
    assert share > 0.7
    assert all(p.share < share / 4 for p in result.pairs[1:])
    assert result.top_for()['copier'][1] == 'original'
    shares = similarity_report.all_shares(result)
    assert len(shares) == 8 * 7 // 2        # every pair, those sharing nothing as 0
    counts = similarity_report.histogram(shares)
    top = min(len(counts) - 1, int(share * len(counts)))      # 100 %: the last bin
    assert counts[top] == 1 and sum(counts[len(counts) // 4:]) == 1


def test_template_and_course_file_alone_flag_nobody(made):
    _, template, folder = made
    students = [s for s in _read(folder) if s.name.startswith('student_')]
    for sub in students:        # their own code gone: template and course file only
        sub.files = {rel: fp for rel, fp in sub.files.items() if rel != 'scripts/brain.py'}
    result = pairs.compare(students, similarity.template_hashes([template]))
    assert result.pairs == [] and sorted(result.empty) == sorted(s.name for s in students)
    assert {rel for _, _, rel, _ in result.base.values()} == {'scripts/lab_utils.py'}


def test_without_a_template_everyone_shares_it(made):
    _, _, folder = made
    subs = _read(folder)[:3]        # three: the template's code is not base code yet
    result = pairs.compare(subs, base_limit=5)
    assert len(result.pairs) == 3 and min(p.share for p in result.pairs) > 0.3


def test_fingerprints_are_the_same_in_every_process():
    """copydetect hashes with Python's hash(), salted per process: two
    processes with other salts agree on the grader's."""
    src = os.path.join(HERE, '..', '..', 'src')
    code = ('from exp_assignment2.grading.similarity import fingerprints as f; '
            'print(sorted(f.fingerprint(open(%r).read(), "x.py", "python").hashes)[:20])'
            % os.path.join(src, 'exp_assignment2', 'grading', 'similarity', 'pairs.py'))
    seen = {subprocess.run([sys.executable, '-c', code], stdout=subprocess.PIPE, check=True,
                           env=dict(os.environ, PYTHONPATH=src, PYTHONHASHSEED=seed),
                           universal_newlines=True).stdout for seed in ('1', '2')}
    assert len(seen) == 1 and len(seen.pop()) > 100


def test_base_limit_is_moss_m():
    assert similarity.default_base_limit(8) == 3
    assert similarity.default_base_limit(300) == 30
    assert similarity.default_base_limit(300, 0.05) == 15


def test_languages():
    assert similarity.language_of('a/x.launch') == 'xml'
    assert similarity.language_of('a/x.cpp') == 'cpp'
    assert similarity.language_of('a/run', '#!/usr/bin/env python3\n') == 'python'
    assert similarity.language_of('a/package.xml') is None
    assert similarity.language_of('a/notes.txt') is None


def test_histogram():
    assert similarity_report.histogram([0.0, 0.01, 0.99, 1.0], 10) == [2] + [0] * 8 + [2]


def test_student_text_is_escaped(tmp_path):
    code = 'def f(a):\n    return "</pre><script>alert(1)</script>" + a * 12345 + a\n' * 4
    for name in ('a', 'b'):
        similarity_fixtures._write(str(tmp_path / name), 'x.py', code)
    subs = _read(str(tmp_path))
    result = pairs.compare(subs)
    text = similarity_report.page(result, [])
    assert '<script>alert' not in text and '&lt;script&gt;alert' in text


def test_report_opens_in_chromium_with_its_image(made, tmp_path):
    root, template, folder = made
    out = str(tmp_path / 'report')
    for name in ('copier', 'student_1'):      # a grading's report, its index without the column
        record.write(os.path.join(out, 'runs', name, 'record'), record.RunRecord.new(
            name, name, 1, verdict='passed', reason='', checks=[]))
    report.write(out, profiles.load('dog'))
    assert '>most shared with</th>' not in open(os.path.join(out, 'index.html')).read()
    assert cli.main([folder, '--template', template, '--similarity-only', '--out', out]) == 0
    data = json.load(open(os.path.join(out, 'similarity.json')))
    assert (data['pairs'][0]['a'], data['pairs'][0]['b']) == ('copier', 'original')
    index = open(os.path.join(out, 'index.html')).read()
    assert 'similarity.html' in index and '>most shared with</th>' in index
    assert index.count('<a href="similarity.html#pair-') == 2     # a cell in each row
    assert 'original</a></td>' in index
    browser = shutil.which('chromium')
    if not browser:
        pytest.skip('no chromium (tools/run test installs it)')
    dom = subprocess.run([browser, '--headless', '--no-sandbox', '--virtual-time-budget=3000',
                          '--dump-dom', 'file://' + os.path.join(out, 'similarity.html')],
                         capture_output=True, text=True, timeout=120).stdout
    assert 'copier and original' in dom and 'data-images-missing="0"' in dom


def test_grading_yaml_template_relative_to_the_folder(made, tmp_path):
    from exp_assignment2.grading.similarity import step as similarity_run
    from exp_assignment2.grading.plan.commands import TeacherFileError, read_teacher_file
    root, template, folder = made
    teacher_file = tmp_path / 'grading.yaml'
    teacher_file.write_text('template: [%s]\n' % os.path.relpath(template, folder))
    teacher = read_teacher_file(str(teacher_file))
    args = options.parse_args([folder])
    assert similarity_run.templates_of(args, teacher, folder) == [template]
    args = options.parse_args([folder, '--template', folder])        # the command line's first
    assert similarity_run.templates_of(args, teacher, folder) == [folder]
    with pytest.raises(TeacherFileError):
        similarity_run.templates_of(options.parse_args([folder, '--template', root + '/nope']),
                                    {}, folder)

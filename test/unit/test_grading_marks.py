"""Scores in the report, the student's page and Gradescope's results.json, from
finished run records alone (exp_assignment2.grading.report.marks, .feedback,
.gradescope; no ROS)."""
import copy
import csv
import json
import os
import sys

from exp_assignment2.grading.report import gradescope
from exp_assignment2.grading.report import index as report
from test_grading_report import write_run
from test_grading_scores import RUBRIC

DOG = RUBRIC        # the marks' mechanics on a rubric of five checks (test_grading_scores)
# Gradescope's documented fields (gradescope-autograders.readthedocs.io, specs)
TOP = {'score', 'execution_time', 'output', 'output_format', 'test_output_format',
       'test_name_format', 'visibility', 'stdout_visibility', 'extra_data', 'tests',
       'leaderboard'}
TEST = {'score', 'max_score', 'status', 'name', 'name_format', 'number', 'output',
        'output_format', 'tags', 'visibility', 'extra_data'}
VISIBILITY = {'hidden', 'after_due_date', 'after_published', 'visible'}


def with_hidden():
    profile = copy.deepcopy(DOG)
    profile['checks'][2]['name'] = 'SECRETCHECK'
    profile['checks'][2]['visibility'] = 'hidden'
    return profile


def class_of_four(tmp_path, profile):
    runs = str(tmp_path / 'runs')
    work = os.path.join(runs, 'ben', 'work')
    checks = lambda values, passed: [  # noqa: E731
        {'name': c['name'], 'metric': c['metric'], 'value': v, 'threshold': 't',
         'passed': passed, 'detail': 'd'} for c, v in zip(profile['checks'], values)]
    write_run(runs, 'ann', 'ann', 'passed', 1.0, checks=checks([2, 40.0, 0.8, 5.0, 0], True))
    write_run(runs, 'ben', 'ben', 'crashed', 0.3, checks=checks([1, 50.0, 0.3, 3.0, 1], False),
              reason='dog-5 died (exit code 1): RuntimeError: boom',
              died=[{'node': 'dog-5', 'code': 1, 'exit': '1', 'log': 'logs/command-0.log',
                     'abort': ''}],
              errors=[{'source': 'logs/command-0.log', 'line': 3, 'summary': 'RuntimeError: boom',
                       'excerpt': 'File "%s/src/dog/scripts/dog.py", line 9\nRuntimeError: '
                                  'boom\nFile "/tmp/exp2-grade-x1/runs/ben/work/overlay/ben-1f/src/'
                                  'dog/scripts/b.py"' % work}], error_count=1,
              repeat_command='bash tools/run grade %s/class/ben' % tmp_path)
    write_run(runs, 'cat', 'cat', 'grader_error', 0.0, checks=None,
              reason='the simulator died (sim, exit code -9)')
    write_run(runs, 'dan', 'dan', 'not_built', 0.0, checks=None,
              reason='CMakeLists.txt:3: no such package')
    return report.write(str(tmp_path), profile)


def test_scores_go_to_grades_csv_report_json_and_the_index(tmp_path):
    summaries = class_of_four(tmp_path, DOG)
    assert [summaries[n]['score'] for n in ('ann', 'ben', 'cat', 'dan')] == [100, 83.5, None, 0]
    with open(str(tmp_path / 'grades.csv')) as f:
        rows = {r['submission']: r for r in csv.DictReader(f)}
    assert rows['ann']['score'] == '100' and rows['ann']['max'] == '100'
    assert rows['cat']['score'] == ''               # no score: to be graded again, not 0
    assert rows['ben']['reaches the ball points'] == '30'
    assert rows['ben']['head turns at the ball points'] == '12.5'
    with open(str(tmp_path / 'report.json')) as f:
        ben = {s['name']: s for s in json.load(f)['submissions']}['ben']
    assert [c['points'] for c in ben['checks']] == [30, 15, 12.5, 10, 16]
    assert ben['checks'][0]['max_points'] == 30 and ben['checks'][0]['visibility'] == 'visible'
    assert ben['score'] == sum(c['points'] for c in ben['checks'])
    with open(str(tmp_path / 'index.html')) as f:
        index = f.read()
    order = [index.index('pages/%s.html' % n) for n in ('ann', 'ben', 'dan', 'cat')]
    assert order == sorted(order)                   # best first, no score last
    assert '<svg class="histogram"' in index and '1 with no score' in index


def test_the_students_page_hides_what_it_must(tmp_path):
    class_of_four(tmp_path, with_hidden())
    for name in ('ann', 'ben', 'cat', 'dan'):
        with open(str(tmp_path / 'feedback' / (name + '.html'))) as f:
            page = f.read()
        assert 'SECRETCHECK' not in page                        # no hidden check
        assert str(tmp_path) not in page                        # no teacher's path
        assert os.path.realpath(str(tmp_path)) not in page
        assert not any('>%s<' % other in page or 'Feedback: %s<' % other in page
                       for other in ('ann', 'ben', 'cat', 'dan') if other != name)
        assert 'src="img/' not in page and 'src="/' not in page  # one file: inlined
    with open(str(tmp_path / 'feedback' / 'ben.html')) as f:
        ben = f.read()
    assert 'The node <code>dog-5</code> died' in ben and 'RuntimeError: boom' in ben
    assert 'File &quot;dog/scripts/dog.py&quot;, line 9' in ben         # the package's own path
    assert 'File &quot;dog/scripts/b.py&quot;' in ben and '/tmp/' not in ben   # the sandbox's
    assert 'died (exit code 1): <b>RuntimeError: boom</b>' in ben
    assert 'keep the points they earned' in ben
    assert 'Points from the checks shown here' in ben           # not the hidden one's
    assert 'data:image/png;base64,' in ben                      # the arena, inlined
    with open(str(tmp_path / 'feedback' / 'cat.html')) as f:
        assert 'No score yet' in f.read()
    with open(str(tmp_path / 'feedback' / 'dan.html')) as f:
        assert 'CMakeLists.txt:3: no such package' in f.read()


def check_format(data):
    assert set(data) <= TOP, set(data) - TOP
    assert isinstance(data['output'], str) and data['stdout_visibility'] in VISIBILITY
    assert isinstance(data['execution_time'], int)
    for test in data['tests']:
        assert set(test) <= TEST and {'name', 'max_score', 'output', 'visibility'} <= set(test)
        assert isinstance(test['name'], str) and isinstance(test['max_score'], float)
        assert test['visibility'] in VISIBILITY and isinstance(test['output'], str)


def test_results_json_in_gradescopes_format(tmp_path):
    class_of_four(tmp_path, with_hidden())
    got = {}
    for name in ('ann', 'ben', 'cat', 'dan'):
        with open(str(tmp_path / 'gradescope' / name / 'results.json')) as f:
            got[name] = json.load(f)
        check_format(got[name])
    ann, ben, cat, dan = (got[n] for n in ('ann', 'ben', 'cat', 'dan'))
    assert ann['score'] == 100 and all(t['status'] == 'passed' for t in ann['tests'])
    assert sum(t['score'] for t in ben['tests']) == ben['score'] == 83.5
    assert [t['visibility'] for t in ben['tests']][2] == 'hidden'    # Gradescope hides it
    assert 'What to fix' in ben['output'] and str(tmp_path) not in json.dumps(ben)
    assert dan['score'] == 0 and 'no such package' in dan['output']
    # a grader error: no score at all, never 0, and says it must be graded again
    assert 'score' not in cat and not any('score' in t for t in cat['tests'])
    assert cat['output'].startswith('NOT GRADED') and 'graded again' in cat['output']


FAKE_GRADE = '''import json, os, sys
out = sys.argv[sys.argv.index('--out') + 1]
os.makedirs(os.path.join(out, 'gradescope', 'submission'))
with open(os.path.join(out, 'gradescope', 'submission', 'results.json'), 'w') as f:
    json.dump({'score': 42.0, 'output': os.listdir(sys.argv[1])[0], 'tests': []}, f)
'''


def test_the_autograder_always_writes_a_results_file(tmp_path):
    root = tmp_path / 'autograder'
    (root / 'submission' / 'my_pkg').mkdir(parents=True)
    fake = tmp_path / 'fake_grade.py'
    fake.write_text(FAKE_GRADE)
    data = gradescope.autograde(str(root), [sys.executable, str(fake)], log=lambda t: None)
    with open(str(root / 'results' / 'results.json')) as f:
        assert json.load(f) == data == {'score': 42.0, 'output': 'my_pkg', 'tests': []}
    broken = gradescope.autograde(str(root), [sys.executable, '-c', 'raise SystemExit(3)'],
                                  log=lambda t: None)
    with open(str(root / 'results' / 'results.json')) as f:
        assert json.load(f) == broken
    check_format(broken)
    assert 'score' not in broken and broken['output'].startswith('NOT GRADED')
    assert 'grade exited with 3' in broken['output']


def test_over_repeats_the_median_score_and_its_run(tmp_path):
    runs = str(tmp_path / 'runs')
    values = {'r1': [2, 40.0, 0.8, 5.0, 0], 'r2': [0, None, 0.0, 0.0, 0],
              'r3': [1, 40.0, 0.3, 5.0, 0]}
    for i, (run, figures) in enumerate(sorted(values.items())):
        write_run(runs, 'ann-' + run, 'ann', 'passed', 1.0, seed=i + 1, checks=[
            {'name': c['name'], 'metric': c['metric'], 'value': v, 'threshold': 't',
             'passed': True, 'detail': ''} for c, v in zip(DOG['checks'], figures)])
    write_run(runs, 'ann-r4', 'ann', 'grader_error', 0.0, seed=4, checks=None)
    ann = report.write(str(tmp_path), DOG)['ann']
    assert ann['scores'] == [100, 20, 87.5, None]
    assert (ann['score'], ann['score_run']) == (87.5, 'ann-r3')     # the grader error left out
    with open(str(tmp_path / 'pages' / 'ann.html')) as f:
        assert 'the median of the repeats' in f.read()


def test_a_check_not_judged_waits_for_the_teacher_everywhere(tmp_path):
    """The head could not be told: the pages say "not judged" and why, its 25
    points are neither earned nor lost (pending, to mark by hand: the index,
    grades.csv), Gradescope gives that test no score, and the pages say which
    robot and ball were judged."""
    runs = str(tmp_path / 'runs')
    checks = [{'name': c['name'], 'metric': c['metric'], 'value': v, 'threshold': 't',
               'passed': True, 'judged': True, 'detail': 'd'}
              for c, v in zip(DOG['checks'], [1, 40.0, None, 5.0, 0])]
    checks[2].update(passed=None, judged=False,
                     detail='not judged: no joint turns camera `camera1` on `link_chassis`')
    roles = {'robot': {'name': 'robot2', 'why': '`robot2`: driven', 'absent': False},
             'head': {'name': None, 'why': 'no joint turns camera `camera1`', 'absent': False},
             'camera': {'name': 'robot2/camera1', 'why': '`camera1`', 'absent': False},
             'ball': {'name': 'toy', 'why': '`toy`: a sphere', 'absent': False},
             'namespace': 'robot2'}
    write_run(runs, 'eve', 'eve', 'passed', 1.0, checks=checks, roles=roles,
              reason='not judged: head turns at the ball')
    summary = report.write(str(tmp_path), DOG)['eve']
    assert (summary['score'], summary['max'], summary['pending']) == (75, 100, 25)
    assert summary['checks'][2]['passed'] is None
    with open(str(tmp_path / 'grades.csv')) as f:
        row = next(csv.DictReader(f))
    assert (row['score'], row['pending'], row['head turns at the ball points']) == ('75', '25', '')
    with open(str(tmp_path / 'index.html')) as f:
        index = f.read()
    assert '+ 25 to mark by hand' in index and '>not judged<' in index
    for page in ('pages', 'feedback'):
        with open(str(tmp_path / page / 'eve.html')) as f:
            text = f.read()
        assert 'not judged' in text and 'no joint turns camera <code>camera1</code>' in text
        assert '<code>robot2</code>' in text and '<code>toy</code>' in text
    with open(str(tmp_path / 'gradescope' / 'eve' / 'results.json')) as f:
        results = json.load(f)
    assert results['score'] == 75
    head = results['tests'][2]
    assert 'score' not in head and head['output'].startswith('not judged by the grader')

"""Judged again, and what changed (exp_assignment2.grading.judge.again,
exp_assignment2.grading.report.changes): a run's verdict decided anew from
its records, and every report keeping the marks it published, so that a
regrade lists whose marks changed. No ROS."""
import csv
import json
import os

from exp_assignment2.grading import record
from exp_assignment2.grading.judge import again
from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.report import changes


def summary(name, verdict, score, path_passed=True, path_points=10.0):
    return {'name': name, 'verdict': verdict, 'score': score, 'max': 100.0,
            'checks': [{'name': 'path length', 'value': 12.5, 'passed': path_passed,
                        'points': path_points},
                       {'name': 'no Python error', 'value': 0, 'passed': True,
                        'points': 20.0}]}


def published(tmp_path, *summaries, name='dog'):
    return changes.publish(str(tmp_path), {s['name']: s for s in summaries}, {'name': name})


def test_each_report_keeps_its_marks_and_the_next_lists_what_changed(tmp_path):
    first = published(tmp_path, summary('ann', 'passed', 100), summary('ben', 'failed_checks',
                                                                       40, False, 0.0))
    assert first['number'] == 1 and first['previous'] is None
    assert changes.index_line(str(tmp_path)) == ''
    # a threshold raised: ann's path check fails
    second = published(tmp_path, summary('ann', 'failed_checks', 94, False, 4.0),
                       summary('ben', 'failed_checks', 40, False, 0.0), name='dog-strict')
    assert (second['number'], second['previous']) == (2, 1)
    assert second['changes'] == [{
        'submission': 'ann', 'change': 'mark', 'verdict before': 'passed',
        'verdict after': 'failed_checks', 'score before': 100.0, 'score after': 94.0,
        'max': 100.0, 'checks changed': [
            'path length: passed, 10 points then; failed, 4 points now']}]
    with open(str(tmp_path / 'changes.csv')) as f:
        rows = list(csv.reader(f))
    assert rows == [changes.COLUMNS, ['ann', 'mark', 'passed', 'failed_checks', '100', '94',
                                      '100', 'path length: passed, 10 points then; failed, '
                                             '4 points now']]
    line = changes.index_line(str(tmp_path))
    assert '<a href="changes.html"><b>1 mark changed</b></a>' in line and 'dog-strict' in line
    page = (tmp_path / 'changes.html').read_text()
    assert '<a href="pages/ann.html">ann</a>' in page and 'published/001.json' in page
    # the same marks again: no new entry, the line stays
    assert published(tmp_path, summary('ann', 'failed_checks', 94, False, 4.0),
                     summary('ben', 'failed_checks', 40, False, 0.0),
                     name='dog-strict')['number'] == 2
    assert sorted(os.listdir(str(tmp_path / 'published'))) == ['001.json', '002.json']
    # back to the first profile: a third entry, against the second
    third = published(tmp_path, summary('ann', 'passed', 100),
                      summary('ben', 'failed_checks', 40, False, 0.0), summary('cat', 'passed',
                                                                              100))
    assert [r['change'] for r in third['changes']] == ['mark', 'new']
    assert 'and 1 other change' in changes.index_line(str(tmp_path))
    assert changes.terminal_line(str(tmp_path)).startswith(
        '1 mark changed since the report before (report 3 against 2): ')


def test_the_report_of_an_older_grader_is_the_first(tmp_path):
    (tmp_path / 'report.json').write_text(json.dumps({
        'profile': {'name': 'dog'}, 'submissions': [summary('ann', 'passed', 100)]}))
    entry = published(tmp_path, summary('ann', 'failed_checks', 90, False, 0.0))
    assert entry['previous'] == 1 and entry['changes'][0]['change'] == 'mark'
    assert json.loads((tmp_path / 'published' / '001.json').read_text())['marks']['ann'][
        'verdict'] == 'passed'


def test_a_run_is_judged_again_from_its_records_and_its_record_is_not_written(tmp_path):
    """A record judged by an older profile (passed) whose build failed: its
    verdict is decided anew, the file named from the submission wherever the
    worker ran it; run.json stays as it was."""
    run_dir = tmp_path / 'runs' / 'ann'
    (run_dir / 'work' / 'logs').mkdir(parents=True)
    (run_dir / 'work' / 'logs' / 'build.log').write_text('make: *** [all] Error 2\n')
    error = {'file': '/tmp/exp2-grade-x1/runs/ann/work/src/ann/src/a.cpp', 'line': 3,
             'message': "expected ';'"}
    old = record.write(str(run_dir / 'record'), record.RunRecord.new(
        'ann', 'ann', 1, verdict='passed', reason='', duration=20.0, ended_by='build_failed',
        events=[{'event': 'built', 'rc': 2, 'error': error}], checks=[],
        grader_fault={'what': again.JUDGING_FAULT, 'error': 'KeyError'}))
    written = (run_dir / 'record' / 'run.json').read_bytes()
    [judged] = again.all_rejudged(str(tmp_path / 'runs'), [old],
                                  lambda name: profiles.load('dog'))
    assert (judged['verdict'], judged['reason']) == ('not_built', "ann/src/a.cpp:3: expected ';'")
    assert 'grader_fault' not in judged and 'checks' not in judged
    assert (run_dir / 'record' / 'run.json').read_bytes() == written
    # a record that says itself how it ended is judged on that alone
    told = again.rejudged(str(run_dir), record.RunRecord.new(
        'ann', 'ann', 1, rejected='the submission: no package.xml in it', verdict='passed'),
        profiles.load('dog'))
    assert told['verdict'] == 'not_built' and told['reason'].startswith('the submission')

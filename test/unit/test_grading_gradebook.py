"""The marks as Moodle and Canvas import them, and a git repository's commit
and lateness on the pages and in the score (grading/report/gradebook.py,
commits.py; from finished run records alone, no ROS)."""
import csv
import json
import os

import pytest

from exp_assignment2.grading.plan import profiles
from exp_assignment2.grading.plan.commands import TeacherFileError, read_teacher_file
from exp_assignment2.grading.report import gradebook
from exp_assignment2.grading.report import index as report
from test_grading_marks import class_of_four
from test_grading_report import write_run
from test_grading_scores import GOOD, RUBRIC

# the marks on a rubric of their own (the dog's before its behaviours), with the dog's title
DOG = dict(RUBRIC, title=profiles.load('dog')['title'])
GIT = {'commit': 'a' * 40, 'short': 'aaaaaaa', 'date': '2025-03-03 10:00 +0100',
       'subject': 'the last fix', 'how': 'grading.yaml names it (commit: aaaaaaa)',
       'deadline': '2025-03-01 23:59 +0100', 'extension': False, 'after': 1,
       'late_days': 2, 'late_points': 20.0, 'uncommitted': 0}


def rows(path):
    with open(path, newline='') as f:
        return list(csv.reader(f))


def test_moodle_rows_by_identifier_and_an_empty_cell_for_no_score(tmp_path):
    summaries = class_of_four(tmp_path, DOG)
    teacher = {'students': {'ann': 'S0012', 'ben': 'ben@uni.example', 'cat': 40012},
               'gradebook': {'assignment': 'Assignment 2'}}
    moodle, _ = gradebook.write(str(tmp_path), summaries, teacher, DOG)
    table = rows(moodle)
    assert table[0] == ['Identifier', 'Submission', 'Assignment 2', 'Feedback']
    by_id = {r[0]: r for r in table[1:]}
    assert by_id['S0012'][1:3] == ['ann', '100']
    assert by_id['ben@uni.example'][2] == '83.5'
    assert by_id['40012'][2] == '' and 'graded again' in by_id['40012'][3]   # never 0
    assert by_id['dan'][2] == '0'        # no students: entry: its name; a real 0 (not built)
    assert gradebook.missing_line(summaries, teacher).endswith(': dan')
    assert gradebook.missing_line(summaries, {}) == ''


def test_canvas_columns_points_possible_and_the_identifiers_column(tmp_path):
    summaries = class_of_four(tmp_path, DOG)
    teacher = {'students': {'ann': 'S0012'}}
    _, canvas = gradebook.write(str(tmp_path), summaries, teacher, DOG)
    table = rows(canvas)
    assert table[0] == ['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section',
                        DOG['title']]
    assert table[1] == ['Points Possible', '', '', '', '', '100']
    by_name = {r[0]: r for r in table[2:]}
    assert by_name['ann'] == ['ann', '', 'S0012', '', '', '100']
    assert by_name['cat'][5] == ''
    teacher['gradebook'] = {'canvas_column': 'ID'}
    _, canvas = gradebook.write(str(tmp_path), summaries, teacher, DOG)
    assert {r[0]: r for r in rows(canvas)[2:]}['ann'][1:3] == ['S0012', '']


def test_the_report_writes_both_beside_grades_csv(tmp_path):
    class_of_four(tmp_path, DOG)
    assert os.path.isfile(str(tmp_path / 'gradebook-moodle.csv'))
    assert os.path.isfile(str(tmp_path / 'gradebook-canvas.csv'))


def test_grading_yaml_keys_of_a_term(tmp_path):
    path = tmp_path / 'grading.yaml'
    path.write_text('deadline: 2025-03-01T23:59\nextensions: {ann: 2025-03-04}\n'
                    'late: {per_day: 10, max: 50}\nstudents: {ann: S1, ben: 12}\n'
                    'gradebook: {assignment: A2, canvas_column: SIS Login ID}\n'
                    'submissions:\n  ann: {commit: "0a1b2c3"}\n  ben: {commit: 0123456}\n')
    teacher = read_teacher_file(str(path))
    assert teacher['submissions'] == {'ann': {'commit': '0a1b2c3'}}
    assert 'write the hash in quotes' in teacher['errors']['ben']     # YAML's octal 0123456
    for text, message in (('deadline: soon\n', "'soon' is not an ISO 8601 time"),
                          ('late: {per_day: -1}\n', 'late: must be'),
                          ('late: {max: 5}\n', 'late: must be'),
                          ('extensions: {ann: never}\n', 'extensions: ann'),
                          ('gradebook: {canvas_column: Email}\n', 'canvas_column'),
                          ('students: {ann: [1]}\n', 'students: ann')):
        path.write_text(text)
        with pytest.raises(TeacherFileError, match=message):
            read_teacher_file(str(path))


def test_a_late_commit_graded_on_purpose_loses_its_points_on_every_page(tmp_path):
    runs = str(tmp_path / 'runs')
    full = [{'name': c['name'], 'metric': c['metric'], 'value': v, 'threshold': '', 'passed': True,
             'detail': ''}
            for c, v in zip(DOG['checks'], GOOD)]       # 100 points on time
    write_run(runs, 'ann', 'ann', 'passed', 1.0, git=GIT, checks=full)
    write_run(runs, 'ben', 'ben', 'passed', 1.0, git=dict(GIT, late_days=0, late_points=0.0),
              checks=full)
    summaries = report.write(str(tmp_path), DOG, teacher={'students': {'ann': 'S1'}})
    ann, ben = summaries['ann'], summaries['ben']
    assert ann['score_before_late'] == ben['score'] == 100 and ann['score'] == 80
    assert '20 points off: 2 days late' in ann['score_why']
    page = open(str(tmp_path / 'pages' / 'ann.html')).read()
    assert 'Commit graded' in page and 'aaaaaaa (2025-03-03 10:00 +0100, &quot;the last fix' \
        in page and '2 days late: 20 points off' in page and 'Score 80 / 100' in page
    student = open(str(tmp_path / 'feedback' / 'ann.html')).read()
    assert 'aaaaaaa' in student and '2 days late: 20 points off' in student
    results = json.load(open(str(tmp_path / 'gradescope' / 'ann' / 'results.json')))
    assert results['score'] == 80 and 'aaaaaaa' in results['output']
    assert rows(str(tmp_path / 'gradebook-moodle.csv'))[1][2:] == [
        '80', 'passed; 2 days late: 20 points off']
    again = report.write(str(tmp_path), DOG)        # --report-only: the same, from the records
    assert again['ann']['score'] == 80


def test_no_score_stays_none_when_late():
    summaries = {'x': {'name': 'x', 'score': None, 'score_why': 'grader error'}}
    from exp_assignment2.grading.report import commits
    commits.apply_late(summaries, [{'name': 'x', 'git': GIT}])
    assert summaries['x']['score'] is None

"""The marks as an LMS imports them (no ROS): ``gradebook-moodle.csv`` and
``gradebook-canvas.csv`` beside grades.csv.

Each row is a submission, named by its student's identifier: grading.yaml's
``students: {NAME: ID}``, else the entry's name. The grade column is named
after the assignment (grading.yaml's ``gradebook: {assignment: ...}``, else
the profile's title). A submission with no score (``grader_error``: to be
graded again) has an empty cell, never 0.

* Moodle (Grades > Import > CSV file): the teacher maps ``Identifier`` to the
  user field it holds (ID number, email address or username) and the grade
  column to the assignment's grade item; ``Feedback`` may be mapped to its
  feedback or ignored. Moodle imports an empty cell as "no grade", and stops
  the whole import at an identifier it does not know.
* Canvas (Grades > Import): its own export's columns, ``Student, ID, SIS User
  ID, SIS Login ID, Section`` and the assignment, with a ``Points Possible``
  row under the header; Canvas finds each student by ``ID`` (its user id), else
  ``SIS User ID``, else ``SIS Login ID``: the identifier goes in the one
  grading.yaml's ``gradebook: {canvas_column: ...}`` names (``SIS User ID`` by
  default). A column whose name is not an assignment of the course makes a new
  one, of the Points Possible.
"""
import csv
import os

from exp_assignment2.grading.report.marks import _number

CANVAS_COLUMNS = ('Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section')
CANVAS_IDS = ('ID', 'SIS User ID', 'SIS Login ID')     # where Canvas looks a student up
MOODLE, CANVAS = 'gradebook-moodle.csv', 'gradebook-canvas.csv'


def identifier(name, teacher):
    """The student's identifier: grading.yaml's ``students:``, else the entry's name."""
    given = (teacher.get('students') or {}).get(name)
    return str(given).strip() if given is not None else name


def assignment(teacher, profile):
    return ((teacher.get('gradebook') or {}).get('assignment') or profile.get('title')
            or profile['name'])


def feedback(summary):
    """A short line for Moodle's feedback column (a student may read it)."""
    if summary.get('score') is None:
        return 'not graded yet: to be graded again'
    parts = [summary['verdict'].replace('_', ' ')]
    if summary.get('pending'):
        parts.append('%s points to be marked by hand' % _number(summary['pending']))
    git = summary.get('git') or {}
    if git.get('late_points'):
        parts.append('%d days late: %s points off' % (git['late_days'],
                                                      _number(git['late_points'])))
    return '; '.join(parts)


def write_moodle(path, summaries, teacher, profile):
    with open(path, 'w', newline='', encoding='utf-8') as f:
        writer = csv.writer(f)
        writer.writerow(['Identifier', 'Submission', assignment(teacher, profile), 'Feedback'])
        for name, summary in summaries.items():
            writer.writerow([identifier(name, teacher), name, _number(summary.get('score')),
                             feedback(summary)])


def write_canvas(path, summaries, teacher, profile):
    column = (teacher.get('gradebook') or {}).get('canvas_column') or 'SIS User ID'
    top = max([s['max'] for s in summaries.values() if s.get('max') is not None] or [0])
    with open(path, 'w', newline='', encoding='utf-8') as f:
        writer = csv.writer(f)
        writer.writerow(list(CANVAS_COLUMNS) + [assignment(teacher, profile)])
        writer.writerow(['Points Possible', '', '', '', '', _number(top)])
        for name, summary in summaries.items():
            row = dict.fromkeys(CANVAS_COLUMNS, '')
            row['Student'], row[column] = name, identifier(name, teacher)
            writer.writerow([row[c] for c in CANVAS_COLUMNS] + [_number(summary.get('score'))])


def write(report_dir, summaries, teacher, profile):
    """Both files in ``report_dir``; their paths."""
    teacher = teacher or {}
    paths = os.path.join(report_dir, MOODLE), os.path.join(report_dir, CANVAS)
    write_moodle(paths[0], summaries, teacher, profile)
    write_canvas(paths[1], summaries, teacher, profile)
    return paths


def missing_line(summaries, teacher):
    """A line naming the submissions grading.yaml's ``students:`` leaves out,
    whose identifier is then their entry's name ('' when it names every one,
    or is not given: a student grading their own package has none)."""
    named = (teacher or {}).get('students') or {}
    missing = sorted(n for n in summaries if n not in named)
    if not named or not missing:
        return ''
    return ('gradebooks: %d submission%s identified by %s entry name (grading.yaml\'s '
            'students: maps a name to the LMS\'s identifier): %s' % (
                len(missing), 's' if len(missing) > 1 else '',
                'their' if len(missing) > 1 else 'its', ' '.join(missing[:20]) +
                (' ...' if len(missing) > 20 else '')))

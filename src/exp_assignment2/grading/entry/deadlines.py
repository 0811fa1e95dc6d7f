"""A term's dates (no ROS, no git): the deadline, each student's extension,
the commit a teacher names on purpose, and the late policy.

A time is ISO 8601 (``2025-03-01T23:59``, ``2025-03-01 23:59:30``,
``2025-03-01T23:59+01:00``, ``...Z``), from the command line or grading.yaml
(where YAML may already have read it as a date): without a zone it is the
teacher's machine's local time, as the teacher reads a calendar; a date alone
is the end of that day (23:59:59). The deadline is the command line's
``--deadline`` over grading.yaml's ``deadline:``; a student's own is
grading.yaml's ``extensions: {NAME: TIME}``. The late policy,
``late: {per_day: P, max: M}``, takes P points a day (each day begun counts)
off a commit graded past its student's deadline, M at most, and only when the
teacher chose that commit on purpose (``submissions: NAME: commit:`` or
``at:``): the deadline itself never grades a late commit.
"""
import datetime
import math

from exp_assignment2.grading.teacher_error import TeacherFileError

DAY = 86400.0
LATE_KEYS = ('per_day', 'max')


def parse_time(value, what):
    """An aware datetime from a string, a YAML date or datetime (TeacherFileError:
    one line naming ``what``)."""
    if isinstance(value, datetime.datetime):
        moment = value
    elif isinstance(value, datetime.date):      # a day alone: its end
        moment = datetime.datetime.combine(value, datetime.time(23, 59, 59))
    elif isinstance(value, str) and value.strip():
        text = value.strip()
        try:
            if len(text) == 10:
                moment = datetime.datetime.combine(datetime.date.fromisoformat(text),
                                                   datetime.time(23, 59, 59))
            else:
                moment = datetime.datetime.fromisoformat(text.replace('z', 'Z'))
        except ValueError:
            raise TeacherFileError('%s: %r is not an ISO 8601 time (2025-03-01T23:59, '
                                   'with +01:00 or Z for a zone)' % (what, value))
    else:
        raise TeacherFileError('%s: %r is not a time (2025-03-01T23:59)' % (what, value))
    if moment.tzinfo is None:
        moment = moment.astimezone()        # the teacher's local zone
    return moment


def shown(moment):
    """A time as the pages write it: ``2025-03-01 23:59 +0100``."""
    return moment.strftime('%Y-%m-%d %H:%M %z')


def check(data, where):
    """grading.yaml's dates and late policy, checked (TeacherFileError)."""
    if 'deadline' in data:
        parse_time(data['deadline'], '%s: deadline' % where)
    for name, value in (data.get('extensions') or {}).items():
        parse_time(value, '%s: extensions: %s' % (where, name))
    late = data.get('late')
    if late is not None:
        if not isinstance(late, dict) or 'per_day' not in late or \
                set(late) - set(LATE_KEYS) or not all(
                    isinstance(v, (int, float)) and not isinstance(v, bool) and v >= 0
                    for v in late.values()):
            raise TeacherFileError('%s: late: must be {per_day: POINTS, max: POINTS} '
                                   '(non-negative numbers; max optional)' % where)


def check_own(settings, where):
    """A submission's ``commit:`` (a hash, tag or branch, quoted) or ``at:`` (a time)."""
    if 'commit' in settings and 'at' in settings:
        raise TeacherFileError('%s: commit: or at:, not both' % where)
    if 'commit' in settings and not (isinstance(settings['commit'], str) and
                                     settings['commit'].strip()):
        raise TeacherFileError('%s: commit: %r: write the hash in quotes (YAML reads '
                               'digits as a number)' % (where, settings['commit']))
    if 'at' in settings:
        parse_time(settings['at'], '%s: at' % where)


def unknown_names(teacher, names):
    """Lines for grading.yaml's ``extensions:`` and ``students:`` that name no
    submission of the folder (a typo gives a student no extension)."""
    return ['grading.yaml: %s: %s is no submission of the folder' % (key, who)
            for key in ('extensions', 'students') for who in sorted(teacher.get(key) or {})
            if who not in names]


def deadline_of(name, cli_deadline, teacher):
    """(the submission's deadline or None, whether it is an extension)."""
    own = (teacher.get('extensions') or {}).get(name)
    if own is not None:
        return parse_time(own, 'grading.yaml: extensions: %s' % name), True
    given = cli_deadline if cli_deadline is not None else teacher.get('deadline')
    if given is None:
        return None, False
    return parse_time(given, '--deadline' if cli_deadline is not None
                      else 'grading.yaml: deadline'), False


def late(commit_time, deadline, policy):
    """(days late, points off) of a commit at ``commit_time`` (s since the
    epoch) chosen on purpose: each day begun past the deadline counts."""
    if deadline is None or commit_time <= deadline.timestamp():
        return 0, 0.0
    days = int(math.ceil((commit_time - deadline.timestamp()) / DAY))
    if not policy:
        return days, 0.0
    points = float(policy['per_day']) * days
    if policy.get('max') is not None:
        points = min(points, float(policy['max']))
    return days, points

"""What a page says was judged (no ROS): the robot, its head, the camera shown
and the ball, each found by its role with why (``roles`` of a run's record,
:mod:`exp_assignment2.grading.judge.roles`), and a check's outcome, which may be
"not judged" when a role it needs could not be told."""
import re

from exp_assignment2.grading.judge.metrics import roles_needed
from exp_assignment2.grading.judge.roles import Roles
from exp_assignment2.grading.report.html import e as _e


def why_html(why):
    """A role's why, its `names` as code."""
    return re.sub(r'`([^`]*)`', r'<code>\1</code>', _e(why))


def outcome(check):
    """(css class, word) of a check: passed, failed, or not judged (passed None)."""
    if check.get('passed') is None:
        return 'nj', 'not judged'
    return ('ok', 'passed') if check['passed'] else ('fail', 'failed')


def judged_rows(run, checks):
    """[(what, name or None, why)] of the run's roles that ``checks`` judge."""
    roles, needed = run.get('roles') or {}, roles_needed(checks)
    return [(key, roles[key].get('name'), roles[key].get('why') or '') for key in Roles.KEYS
            if key in needed and isinstance(roles.get(key), dict)]


def judged_section(run, checks, heading='What was judged'):
    """HTML parts: a table of the robot, head, camera and ball the ``checks``
    judged, and why (none: no part)."""
    rows = judged_rows(run, checks)
    if not rows:
        return []
    parts = ['<h2>%s</h2><table><tr><th></th><th>judged</th><th>why</th></tr>' % _e(heading)]
    for label, name, why in rows:
        parts.append('<tr><td>%s</td><td>%s</td><td>%s</td></tr>' % (
            _e(label), '<code>%s</code>' % _e(name) if name is not None
            else '<span class="nj">none</span>', why_html(why)))
    parts.append('</table>')
    return parts

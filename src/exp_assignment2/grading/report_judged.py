"""What a page says was judged (no ROS): the robot, its head, the camera shown
and the ball, each found by its role with why (``roles`` of a run's record,
:mod:`exp_assignment2.grading.roles`), and a check's outcome, which may be
"not judged" when a role it needs could not be told."""
import html
import re

LABELS = (('robot', 'robot'), ('head', 'head'), ('camera', 'camera'), ('ball', 'ball'))


def _e(text):
    return html.escape(str(text if text is not None else ''))


def why_html(why):
    """A role's why, its `names` as code."""
    return re.sub(r'`([^`]*)`', r'<code>\1</code>', _e(why))


def outcome(check):
    """(css class, word) of a check: passed, failed, or not judged (passed None)."""
    if check.get('passed') is None:
        return 'nj', 'not judged'
    return ('ok', 'passed') if check['passed'] else ('fail', 'failed')


def judged_rows(run):
    """[(what, name or None, why)] of the run's roles that the profile judges."""
    roles = run.get('roles') or {}
    rows = []
    for key, label in LABELS:
        role = roles.get(key)
        if not role or (role.get('name') is None and role.get('why') == 'the profile judges '
                                                                         'none'):
            continue
        rows.append((label, role.get('name'), role.get('why') or ''))
    return rows


def judged_section(run, heading='What was judged'):
    """HTML parts: a table of the robot, head, camera and ball judged, and why."""
    rows = judged_rows(run)
    if not rows:
        return []
    parts = ['<h2>%s</h2><table><tr><th></th><th>judged</th><th>why</th></tr>' % _e(heading)]
    for label, name, why in rows:
        parts.append('<tr><td>%s</td><td>%s</td><td>%s</td></tr>' % (
            _e(label), '<code>%s</code>' % _e(name) if name is not None
            else '<span class="nj">none</span>', why_html(why)))
    parts.append('</table>')
    return parts

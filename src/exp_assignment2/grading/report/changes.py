"""What a report changed of the marks before it (no ROS).

Every report written keeps the marks it published in ``published/NNN.json``
(each submission's verdict, score and checks' outcomes and points; the
profile it was judged with; the changes from the one before), a new one
only when the marks or the profile differ from the last: a teacher's
sequence of regrades reads as a numbered list (``changes.html`` shows it).
The newest's changes, per submission (verdict and score before and after,
the checks whose outcome or points changed), are in ``changes.csv`` and
``changes.html``, and the index says how many marks changed, at its top. A
report of an older grader (a ``report.json`` with no ``published/``) is
taken as the first.
"""
import csv
import glob
import json
import os
import time

from exp_assignment2.grading.report.html import e as _e, head

FOLDER = 'published'
COLUMNS = ['submission', 'change', 'verdict before', 'verdict after', 'score before',
           'score after', 'max', 'checks changed']


def _round(value):
    return None if value is None else round(float(value), 2)


def marks_of(summaries):
    """{name: {'verdict', 'score', 'max', 'checks': {name: {passed, points, value}}}}
    of the report's summaries (or of an older report.json's submissions)."""
    return {s['name']: {'verdict': s['verdict'], 'score': _round(s.get('score')),
                        'max': _round(s.get('max')),
                        'checks': {c['name']: {'passed': c.get('passed'),
                                               'points': _round(c.get('points')),
                                               'value': c.get('value')}
                                   for c in s.get('checks') or []}}
            for s in summaries}


def _checks_changed(before, after):
    """['NAME: passed, 10 points then; failed, 4 now'] of the checks whose
    outcome or points differ."""
    said = []
    for name in list(after) + [n for n in before if n not in after]:
        b, a = before.get(name) or {}, after.get(name) or {}
        if (b.get('passed'), b.get('points')) != (a.get('passed'), a.get('points')):
            said.append('%s: %s then; %s now' % (name, _outcome(b), _outcome(a)))
    return said


def _outcome(check):
    if not check:
        return 'not there'
    word = {True: 'passed', False: 'failed', None: 'not judged'}[check.get('passed')]
    return word + ('' if check.get('points') is None else ', %g points' % check['points'])


def changes(before, after):
    """[row] per submission whose mark (verdict or score) or checks changed,
    new or gone: each {submission, change: mark | checks | new | gone, ...}."""
    rows = []
    for name in sorted(set(before) | set(after)):
        b, a = before.get(name), after.get(name)
        row = {'submission': name, 'verdict before': (b or {}).get('verdict'),
               'verdict after': (a or {}).get('verdict'), 'score before': (b or {}).get('score'),
               'score after': (a or {}).get('score'), 'max': (a or b).get('max'),
               'checks changed': []}
        if b is None or a is None:
            row['change'] = 'new' if b is None else 'gone'
        else:
            row['checks changed'] = _checks_changed(b['checks'], a['checks'])
            if (b['verdict'], b['score']) != (a['verdict'], a['score']):
                row['change'] = 'mark'
            elif row['checks changed']:
                row['change'] = 'checks'
            else:
                continue
        rows.append(row)
    return rows


def _read(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def history(report_dir):
    """[every published entry], oldest first."""
    found = (_read(p) for p in sorted(glob.glob(os.path.join(report_dir, FOLDER, '*.json'))))
    return [entry for entry in found if isinstance(entry, dict) and 'marks' in entry]


def _older_report(report_dir):
    """The first entry, from the report.json of a grader that kept no history."""
    path = os.path.join(report_dir, 'report.json')
    old = _read(path)
    if not isinstance(old, dict) or not isinstance(old.get('submissions'), list):
        return None
    return {'number': 1, 'at': os.path.getmtime(path),
            'profile': (old.get('profile') or {}).get('name'), 'previous': None,
            'marks': marks_of(old['submissions']), 'changes': []}


def _put(report_dir, entry):
    os.makedirs(os.path.join(report_dir, FOLDER), exist_ok=True)
    path = os.path.join(report_dir, FOLDER, '%03d.json' % entry['number'])
    with open(path + '.tmp', 'w') as f:
        json.dump(entry, f, indent=1, default=str)
    os.replace(path + '.tmp', path)


def publish(report_dir, summaries, profile):
    """Keep the marks of the report being written (before its report.json);
    write changes.csv and changes.html; the newest entry."""
    entries = history(report_dir)
    if not entries:
        first = _older_report(report_dir)
        if first is not None:
            _put(report_dir, first)
            entries = [first]
    marks = json.loads(json.dumps(marks_of(summaries.values()), default=str))
    last = entries[-1] if entries else None
    rows = changes(last['marks'], marks) if last else []
    if last is None or rows or last.get('profile') != profile['name']:
        last = {'number': (last['number'] + 1) if last else 1, 'at': time.time(),
                'profile': profile['name'], 'previous': last['number'] if last else None,
                'marks': marks, 'changes': rows}
        _put(report_dir, last)
        entries.append(last)
    _write_csv(os.path.join(report_dir, 'changes.csv'), last['changes'])
    with open(os.path.join(report_dir, 'changes.html'), 'w') as f:
        f.write(_page(entries))
    return last


def _when(at):
    return time.strftime('%Y-%m-%d %H:%M', time.localtime(at))


def _count(entry):
    rows = entry.get('changes') or []
    return sum(r['change'] == 'mark' for r in rows), len(rows)


def _marks(count):
    return '%d mark%s' % (count, '' if count == 1 else 's')


def _score(value):
    return '' if value is None else '%g' % value


def _write_csv(path, rows):
    with open(path, 'w', newline='') as f:
        writer = csv.writer(f)
        writer.writerow(COLUMNS)
        for row in rows:
            writer.writerow([row['submission'], row['change'], row['verdict before'] or '',
                             row['verdict after'] or '', _score(row['score before']),
                             _score(row['score after']), _score(row['max']),
                             '; '.join(row['checks changed'])])


def _page(entries):
    last = entries[-1]
    parts = [head('What changed', 'td,th{padding:2px 8px}'),
             '<p><a href="index.html">&larr; the report</a></p><h1>What changed</h1>']
    if last['previous'] is None:
        parts.append('<p>The first report: nothing to compare with.</p>')
    else:
        before = next((e for e in entries if e['number'] == last['previous']), None)
        parts.append('<p>Report %d (%s, profile %s) against report %d%s: %s changed. '
                     'Also in <a href="changes.csv">changes.csv</a>.</p>' % (
                         last['number'], _e(_when(last['at'])), _e(last['profile']),
                         last['previous'], ' (%s, profile %s)' % (
                             _e(_when(before['at'])), _e(before['profile'])) if before else '',
                         _marks(_count(last)[0])))
        parts.append('<table><tr>%s</tr>' % ''.join('<th>%s</th>' % _e(c) for c in COLUMNS))
        for row in last['changes']:
            parts.append('<tr><td><a href="pages/%s.html">%s</a></td><td>%s</td><td>%s</td>'
                         '<td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td></tr>' % (
                             _e(row['submission']), _e(row['submission']), _e(row['change']),
                             _e(row['verdict before'] or '—'), _e(row['verdict after'] or '—'),
                             _e(_score(row['score before'])), _e(_score(row['score after'])),
                             _e(_score(row['max'])),
                             '<br>'.join(_e(c) for c in row['checks changed'])))
        parts.append('</table>')
    parts.append('<h2>Every report published here</h2><table><tr><th>report</th><th>when</th>'
                 '<th>profile</th><th>marks changed</th><th>its marks</th></tr>')
    for entry in reversed(entries):
        parts.append('<tr><td>%d</td><td>%s</td><td>%s</td><td>%s</td>'
                     '<td><a href="%s/%03d.json">%03d.json</a></td></tr>' % (
                         entry['number'], _e(_when(entry['at'])), _e(entry['profile']),
                         '—' if entry['previous'] is None else _count(entry)[0], FOLDER,
                         entry['number'], entry['number']))
    parts.append('</table></body></html>')
    return ''.join(parts)


def index_line(report_dir):
    """The index's line at its top: how many marks the newest report
    changed, linking to the list ('' for the first report)."""
    entries = history(report_dir)
    if not entries or entries[-1]['previous'] is None:
        return ''
    last = entries[-1]
    marks, rows = _count(last)
    return ('<p class="changes"><a href="changes.html"><b>%s changed</b></a> since '
            'the report of %s%s%s.</p>' % (
                _marks(marks), _e(_when(
                    next((e['at'] for e in entries if e['number'] == last['previous']),
                         last['at']))),
                '' if rows == marks else ' (and %d other change%s: checks, new or gone '
                'submissions)' % (rows - marks, '' if rows - marks == 1 else 's'),
                ', judged with profile %s' % _e(last['profile'])))


def terminal_line(report_dir):
    """The terminal's line on what the newest report changed ('' for the first)."""
    entries = history(report_dir)
    if not entries or entries[-1]['previous'] is None:
        return ''
    marks, rows = _count(entries[-1])
    return '%s changed since the report before (report %d against %d): %s' % (
        _marks(marks), entries[-1]['number'], entries[-1]['previous'],
        os.path.join(report_dir, 'changes.html'))

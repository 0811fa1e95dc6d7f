"""The report's marks (no ROS): each submission's score from its runs
(:mod:`exp_assignment2.grading.judge.scores`), its columns in ``grades.csv``, its
cell in ``index.html`` and the class's distribution as an inline SVG."""
import csv

from exp_assignment2.grading.judge import scores
from exp_assignment2.grading.report.html import e


def add_scores(summaries, runs, profile):
    """Give each summary ``score`` (None: no score, to be run again), ``max``,
    ``score_why``, ``score_run`` (the median run's label) and, on each of its
    checks, ``points``, ``max_points`` and ``visibility`` (the median run's)."""
    for name, summary in summaries.items():
        scored = [(r, scores.run_score(r, profile)) for r in runs if r['name'] == name]
        chosen = scores.median_run(scored) or scored[0]
        run, marks = chosen
        summary.update(score=marks['score'], max=marks['max'], score_why=marks['why'],
                       score_run=run['label'], score_checks=marks['checks'],
                       scores=[m['score'] for _, m in scored], pending=marks.get('pending', 0))
        by_name = {c['name']: c for c in marks['checks']}
        for check in summary['checks']:
            check.update({k: v for k, v in by_name.get(check['name'], {}).items()
                          if k in ('points', 'max_points', 'visibility')})
    return summaries


def _number(value):
    if value is None:
        return ''
    return ('%g' % round(value, 2))


def csv_header(profile):
    """The columns grades.csv gains: after ``flaky``, and after the figures
    (``pending``: points of checks the grader could not run, to mark by hand)."""
    return ['score', 'max', 'pending'], ['%s points' % c['name'] for c in profile['checks']]


def csv_cells(summary, profile):
    points = {c['name']: c['points'] for c in summary.get('score_checks') or []}
    return ([_number(summary.get('score')), _number(summary.get('max')),
             _number(summary.get('pending') or 0)],
            [_number(points.get(c['name'])) for c in profile['checks']])


def by_score(summaries):
    """The summaries, best score first (no score last), then by name."""
    return sorted(summaries.values(), key=lambda s: (s.get('score') is None,
                                                     -(s.get('score') or 0), s['name']))


def score_cell(summary):
    """The index's score cell (sorts by its number; no score sorts last)."""
    if summary.get('score') is None:
        return '<td data-key="-1" title="%s">no score</td>' % e(
            summary.get('score_why') or '')
    return '<td data-key="%s" title="%s"><b>%s</b> / %s%s</td>' % (
        summary['score'], e(summary.get('score_why') or ''),
        _number(summary['score']), _number(summary['max']),
        ' <span class="nj">+ %s to mark by hand</span>' % _number(summary['pending'])
        if summary.get('pending') else '')


def histogram_svg(summaries, bins=10, width=420, height=120):
    """The class's scores in ``bins`` bars over 0..max, an inline SVG ('' without scores)."""
    got = [s for s in summaries.values() if s.get('score') is not None]
    if not got:
        return ''
    top = max(s['max'] for s in got) or 1.0
    counts = [0] * bins
    for s in got:
        counts[min(bins - 1, int(s['score'] / top * bins))] += 1
    tallest = max(counts)
    bar = (width - 40) / float(bins)
    parts = ['<svg class="histogram" xmlns="http://www.w3.org/2000/svg" width="%d" height="%d"'
             ' role="img" aria-label="the class\'s scores">' % (width, height + 20)]
    for i, n in enumerate(counts):
        h = (height - 20) * n / float(tallest)
        x = 30 + i * bar
        parts.append('<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="#1565c0">'
                     '<title>%g to %g: %d</title></rect>' % (
                         x + 1, height - h, bar - 2, h, top * i / bins,
                         top * (i + 1) / bins, n))
        if n:
            parts.append('<text x="%.1f" y="%.1f" font-size="11" text-anchor="middle">%d</text>'
                         % (x + bar / 2, height - h - 3, n))
    for i in range(0, bins + 1, 2):
        parts.append('<text x="%.1f" y="%d" font-size="11" text-anchor="middle">%g</text>'
                     % (30 + i * bar, height + 14, round(top * i / bins, 1)))
    parts.append('<line x1="30" y1="%d" x2="%d" y2="%d" stroke="#555"/></svg>'
                 % (height, width - 10, height))
    none = len(summaries) - len(got)
    return ('<p>Scores (out of %s)%s:</p>%s' % (
        _number(top), ', %d with no score (a grader error: to be graded again)' % none
        if none else '', ''.join(parts)))


def score_paragraph(summary):
    """The teacher's page's line on the score: how much, and why (a crash's kept points)."""
    if summary.get('score') is None:
        return '<p><b>No score</b>: %s</p>' % e(summary.get('score_why') or '')
    return '<p><b>Score %s / %s</b>%s%s</p>' % (
        _number(summary['score']), _number(summary['max']),
        ': ' + e(summary['score_why']) if summary.get('score_why') else '',
        ' (the median of the repeats\' %s, from run %s)' % (
            ', '.join('no score' if v is None else _number(v) for v in summary['scores']),
            e(summary['score_run'])) if len(summary.get('scores') or ()) > 1 else '')


def points_cell(check):
    """A check's points on the teacher's page, with who else sees it."""
    if 'max_points' not in check:
        return '<td></td>'
    return '<td>%s / %s%s</td>' % (
        'to mark by hand' if check.get('pending') or check.get('passed', False) is None else
        'no score' if check.get('points') is None else _number(check['points']),
        _number(check['max_points']), '' if check.get('visibility', 'visible') == 'visible'
        else ' <small>(%s)</small>' % e(check['visibility']))


def write_csv(path, summaries, profile):
    """grades.csv: a row a submission, its verdict, marks, each check's figure and points."""
    with open(path, 'w', newline='') as f:
        writer = csv.writer(f)
        names = [c['name'] for c in profile['checks']]
        marks, points = csv_header(profile)
        writer.writerow(['submission', 'verdict', 'flaky'] + marks + names + points + ['reason'])
        for s in summaries.values():
            values = {c['name']: c['value'] for c in s['checks']}
            marks, points = csv_cells(s, profile)
            writer.writerow([s['name'], s['verdict'], int(s['flaky'])] + marks +
                            [values.get(n, '') for n in names] + points + [s['reason']])

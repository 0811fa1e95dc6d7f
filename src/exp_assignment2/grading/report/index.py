"""The grading's report, made from the runs' records only (no ROS; ``grade
--report-only`` makes it again without running anything).

In REPORT_DIR: ``index.html`` (one row per submission, sortable, opens from the file system;
written once, with the similarity report's column when one is there),
``pages/<name>.html`` (:mod:`~exp_assignment2.grading.report.pages`: the commands, the
verdict, the arena from above, the head's angle, the frames, the log excerpts, the build
log), ``report.json`` (everything), ``grades.csv`` (one line
each, with the scores: :mod:`~exp_assignment2.grading.report.marks`), ``feedback/<name>.html`` (the
student's page: :mod:`~exp_assignment2.grading.report.feedback`) and
``gradescope/<name>/results.json`` (:mod:`~exp_assignment2.grading.report.gradescope`).
"""
import collections
import json
import os
import shutil
import statistics

from exp_assignment2.grading import record
from exp_assignment2.grading.judge.verdicts import VERDICTS
from exp_assignment2.grading.report import changes as report_changes
from exp_assignment2.grading.report import commits as report_commits
from exp_assignment2.grading.report import feedback
from exp_assignment2.grading.report import gradebook
from exp_assignment2.grading.report import gradescope
from exp_assignment2.grading.report import judged as report_judged
from exp_assignment2.grading.report import marks as report_marks
from exp_assignment2.grading.report import pages as teacher_pages
from exp_assignment2.grading.report import releases as report_releases
from exp_assignment2.grading.report import resumed as report_resumed
from exp_assignment2.grading.report.html import IMAGES_JS, e as _e, figure, head
from exp_assignment2.grading.similarity import page as similarity_page

SORT_JS = '''function sortBy(th){var
t=th.closest('table'),i=[].indexOf.call(th.parentNode.children,th),
b=t.tBodies[0],rows=[].slice.call(b.rows),asc=th.dataset.asc!=='1';th.dataset.asc=asc?'1':'0';
rows.sort(function(x,y){var a=x.cells[i].dataset.key||x.cells[i].textContent,
c=y.cells[i].dataset.key||y.cells[i].textContent,na=parseFloat(a),nc=parseFloat(c); var
r=(!isNaN(na)&&!isNaN(nc))?na-nc:a.localeCompare(c);return asc?r:-r;});
rows.forEach(function(r){b.appendChild(r);});}'''


def load_runs(runs_dir):
    """[run record] of every run directory that has one (read by grading.record)."""
    return record.load_all(runs_dir)


def _majority(verdicts):
    counts = collections.Counter(verdicts)
    best = max(counts.values())
    # a tie goes to the worse verdict: a grade should not rest on luck
    return max((v for v in counts if counts[v] == best), key=VERDICTS.index)


def summarise(runs):
    """{name: submission summary} over the runs of each submission (repeats)."""
    by_name = collections.OrderedDict()
    for run in runs:
        by_name.setdefault(run['name'], []).append(run)
    out = collections.OrderedDict()
    for name, group in by_name.items():
        verdicts = [r['verdict'] for r in group]
        verdict = _majority(verdicts)
        checks = []
        for i, check in enumerate(next((r['checks'] for r in group if r.get('checks')), [])):
            values = [r['checks'][i]['value'] for r in group
                      if r.get('checks') and r['checks'][i]['value'] is not None]
            judged = [r['checks'][i] for r in group
                      if r.get('checks') and r['checks'][i].get('passed') is not None]
            checks.append(dict(check, value=statistics.median(values) if values else None,
                               values=values, judged=bool(judged),    # None: never judged
                               passed=sum(c['passed'] for c in judged) * 2 > len(judged)
                               if judged else None))
        main = next((r for r in group if r['verdict'] == verdict), group[0])
        out[name] = {'name': name, 'verdict': verdict, 'flaky': len(set(verdicts)) > 1,
                     'verdicts': verdicts, 'checks': checks, 'reason': main.get('reason', ''),
                     'runs': [r['label'] for r in group], 'main_run': main['label'],
                     'commands': main.get('commands'), 'commands_from': main.get('commands_from'),
                     'real_time_factor': [r.get('real_time_factor') for r in group],
                     'slow': any((r.get('real_time_factor') or 1.0) < 0.95 * (
                         r.get('real_time_factor_asked') or 1.0) for r in group
                         if r.get('real_time_factor') is not None),
                     'seeds': [r.get('seed') for r in group],
                     'died': main.get('died') or [], 'roles': main.get('roles') or {},
                     'launch_errors': main.get('launch_errors') or []}
    return out


def _index(summaries, pictures, profile, title, similar=None, top=()):
    """index.html's text; ``similar``: similarity.json's tops (its column), or None;
    ``top``: [HTML] said first (the marks changed, a resumed or stopped grading)."""
    check_names = [c['name'] for c in profile['checks']]
    counts = collections.Counter(s['verdict'] for s in summaries.values())
    parts = [head(title, teacher_pages.STYLE, SORT_JS + IMAGES_JS),
             '<h1>%s</h1>%s<p>%d submissions: %s. Click a heading to sort.</p>' % (
                 _e(title), similarity_page.INDEX_LINK if similar is not None else '',
                 len(summaries),
                 ', '.join('%d %s' % (counts[v], v) for v in VERDICTS if counts[v])),
             ''.join(top), report_marks.histogram_svg(summaries),
             '<table><thead><tr><th onclick="sortBy(this)">submission</th>%s'
             '<th onclick="sortBy(this)">score</th><th onclick="sortBy(this)">verdict</th>'
             % (similarity_page.INDEX_HEADING if similar is not None else '')]
    parts += ['<th onclick="sortBy(this)">%s</th>' % _e(n) for n in check_names]
    parts.append('<th onclick="sortBy(this)">first error</th><th>picture</th></tr></thead><tbody>')
    for s in report_marks.by_score(summaries):
        name, values = s['name'], {c['name']: c for c in s['checks']}
        shared = similarity_page.index_cell(name, similar) if similar is not None else ''
        parts.append('<tr><td><a href="pages/%s.html">%s</a></td>%s%s<td data-key="%d">%s%s</td>'
                     % (_e(name), _e(name), shared, report_marks.score_cell(s),
                        VERDICTS.index(s['verdict']), teacher_pages.verdict_badge(s['verdict']),
                        ' <span class="flaky">flaky</span>' if s['flaky'] else ''))
        for check_name in check_names:
            check = values.get(check_name)
            if check is None:
                parts.append('<td data-key="-1">—</td>')
            else:
                parts.append('<td class="%s" data-key="%s">%s</td>' % (
                    report_judged.outcome(check)[0],
                    check['value'] if check['value'] is not None else -1,
                    _e(figure(check['value'], '—') if check.get('passed') is not None
                       else 'not judged')))
        parts.append('<td>%s</td>' % _e(s['reason'][:160]))
        thumb = pictures.get(name, {}).get('thumb')
        parts.append('<td>%s</td></tr>' % ('<img src="pages/img/%s" alt="%s">' % (
            os.path.basename(thumb), _e(name)) if thumb else ''))
    parts.append('</tbody></table></body></html>')
    return ''.join(parts)


def _summaries(report_dir, profile, every=None):
    """(every run's record, the runs that count, {name: summary}) of
    ``report_dir/runs`` (``every``: their records, judged again)."""
    every = load_runs(os.path.join(report_dir, 'runs')) if every is None else every
    runs, tried = report_releases.counted(every, profile)   # in several releases: the better
    summaries = report_marks.add_scores(summarise(runs), runs, profile)
    report_commits.apply_late(summaries, runs)      # a late commit graded on purpose
    for name, summary in summaries.items():
        summary['releases'] = tried.get(name) or []
    return every, runs, summaries


def _write_index(report_dir, summaries, pictures, profile, title):
    """index.html, once, with the similarity column when a similarity report is there."""
    title = title or 'Grading: %s' % (profile.get('title') or profile['name'])
    with open(os.path.join(report_dir, 'index.html'), 'w') as f:
        f.write(_index(summaries, pictures, profile, title, similarity_page.tops(report_dir),
                       [report_changes.index_line(report_dir)] +
                       report_resumed.paragraph(report_dir)))


def write(report_dir, profile, title=None, teacher=None, runs=None):
    """Make the report from ``report_dir/runs`` (``runs``: their records,
    judged again: judge.again); returns the summaries. ``teacher``:
    grading.yaml's settings (the gradebooks' identifiers). The marks it
    publishes are kept beside the earlier ones (report.changes)."""
    runs_dir = os.path.join(report_dir, 'runs')
    every, runs, summaries = _summaries(report_dir, profile, runs)
    report_changes.publish(report_dir, summaries, profile)
    pages = os.path.join(report_dir, 'pages')
    img_dir = os.path.join(pages, 'img')
    shutil.rmtree(pages, ignore_errors=True)
    os.makedirs(img_dir)
    pictures = {}
    for name, summary in summaries.items():
        group = [r for r in runs if r['name'] == name]
        main = next(r for r in group if r['label'] == summary['main_run'])
        pictures[name] = teacher_pages.pictures(main, runs_dir, img_dir, profile)
        with open(os.path.join(pages, name + '.html'), 'w') as f:
            f.write(teacher_pages.page(summary, group, runs_dir, pictures[name], profile))
    feedback.write_all(report_dir, summaries, runs, pictures, profile)      # the students'
    gradescope.write_all(report_dir, summaries, runs, profile)
    _write_index(report_dir, summaries, pictures, profile, title)
    with open(os.path.join(report_dir, 'report.json'), 'w') as f:
        json.dump({'profile': profile, 'submissions': list(summaries.values()), 'runs': every},
                  f, indent=1, default=str)
    report_marks.write_csv(os.path.join(report_dir, 'grades.csv'), summaries, profile)
    gradebook.write(report_dir, summaries, teacher, profile)     # Moodle's and Canvas's
    return summaries


def write_index(report_dir, profile, title=None):
    """index.html alone, from the runs' records and the pictures already there
    (``--similarity-only`` after a grading: its column); the summaries."""
    _, runs, summaries = _summaries(report_dir, profile)
    img_dir = os.path.join(report_dir, 'pages', 'img')
    pictures = {}
    for name, summary in summaries.items():
        thumb = os.path.join(img_dir, summary['main_run'] + '_thumb.jpg')
        pictures[name] = {'thumb': thumb} if os.path.isfile(thumb) else {}
    _write_index(report_dir, summaries, pictures, profile, title)
    return summaries

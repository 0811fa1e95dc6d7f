"""The grading's report, made from the runs' records only (no ROS; ``grade
--report-only`` makes it again without running anything).

In REPORT_DIR: ``index.html`` (one row per submission, sortable, opens from the file system),
``pages/<name>.html`` (the commands, the verdict, the arena from above, the head's angle, the
frames, the log excerpts, the build log), ``report.json`` (everything), ``grades.csv`` (one line
each, with the scores: :mod:`~exp_assignment2.grading.report.marks`), ``feedback/<name>.html`` (the
student's page: :mod:`~exp_assignment2.grading.report.feedback`) and
``gradescope/<name>/results.json`` (:mod:`~exp_assignment2.grading.report.gradescope`).
"""
import collections
import json
import os
import shutil
import statistics

from exp_assignment2.grading.report import evidence
from exp_assignment2.grading.report import feedback
from exp_assignment2.grading.report import figures
from exp_assignment2.grading.report import gradescope
from exp_assignment2.grading.judge import metrics
from exp_assignment2.grading import record
from exp_assignment2.grading.report import failures as report_failures
from exp_assignment2.grading.report import judged as report_judged
from exp_assignment2.grading.report import marks as report_marks
from exp_assignment2.grading.report import packages as report_packages
from exp_assignment2.grading.report import releases as report_releases
from exp_assignment2.grading.report import starts as report_starts
from exp_assignment2.grading.judge import roles as roles_
from exp_assignment2.grading.judge.logs import read_log
from exp_assignment2.grading.report.camera import camera_section, window_pictures
from exp_assignment2.grading.judge.verdicts import VERDICTS
from exp_assignment2.grading.report.html import IMAGES_JS, e as _e, figure, head

COLOURS = {'passed': '#2e7d32', 'failed_checks': '#ef6c00', 'crashed': '#c62828',
           'timed_out': '#6a1b9a', 'not_started': '#ad1457', 'not_built': '#4e342e',
           'grader_error': '#546e7a'}
STYLE = '''th{cursor:pointer}.v{color:#fff;padding:2px 6px;
border-radius:3px;white-space:nowrap}.frames img{margin-right:6px}.frames
img.window{max-width:760px} .flaky{background:#fff3cd;padding:1px 4px}
.nj{font-style:italic}'''
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


def _verdict_badge(verdict, pending=0):
    """The verdict, and the points a person must still mark (checks not judged)."""
    return '<span class="v" style="background:%s">%s</span>%s' % (
        COLOURS.get(verdict, '#333'), verdict,
        ' <span class="nj">%s points to mark by hand</span>' % report_marks._number(pending)
        if pending else '')


def _run_pictures(run, runs_dir, img_dir, profile):
    """The run's figures and chosen frames, copied next to its page."""
    record = os.path.join(runs_dir, run['label'], 'record')
    trace = metrics.Trace.from_record(record)
    roles = roles_.of_run(run, trace, profile)
    label = run['label']
    pictures = {}
    shown = evidence.pictures(record, trace, roles, run, img_dir)     # the checks' moments
    pictures['evidence'] = shown
    top = figures.top_view(trace, roles, os.path.join(img_dir, label + '_top.png'),
                           marks=[(m[0], m[2]) for m in shown['moments']])
    if top:
        pictures['top'] = top
    head = figures.head_angle(trace, roles, os.path.join(img_dir, label + '_head.png'))
    if head:
        pictures['head'] = head
    frames, times = {}, {}
    for moment, source in figures.chosen_frames(record, trace, roles).items():
        target = os.path.join(img_dir, '%s_%s.jpg' % (label, moment.replace(' ', '_')))
        shutil.copy(source, target)
        frames[moment], times[moment] = target, figures.frame_time(source)
    pictures['frames'] = frames
    pictures['windows'] = window_pictures(label, runs_dir, img_dir, record, times)
    thumb_source = frames.get('closest approach') or frames.get('end') or top
    if thumb_source:
        thumb = figures.thumbnail(thumb_source, os.path.join(img_dir, label + '_thumb.jpg'))
        if thumb:
            pictures['thumb'] = thumb
    return pictures


def _page(summary, runs, runs_dir, pictures, profile):
    main = next(r for r in runs if r['label'] == summary['main_run'])
    rel = lambda p: 'img/' + os.path.basename(p)   # noqa: E731
    parts = [head(summary['name'], STYLE, IMAGES_JS),
             '<p><a href="../index.html">&larr; all submissions</a></p>',
             '<h1>%s %s</h1>' % (_e(summary['name']), _verdict_badge(summary['verdict'],
                                                                    summary.get('pending'))),
             '<p>%s</p>' % _e(summary['reason']), report_marks.score_paragraph(summary)]
    if summary['flaky']:
        parts.append('<p class="flaky">flaky: the repeats ended %s</p>'
                     % _e(', '.join(summary['verdicts'])))
    parts.append('<h2>Started with</h2><p>from %s</p>%s' % (
        _e(main.get('commands_from')), report_starts.table(main)))
    for note in main.get('notes') or []:
        parts.append('<p>note: %s</p>' % _e(note))
    parts += report_packages.packages_section(main)
    parts += report_releases.releases_section(main, summary.get('releases'))
    if main.get('readme_commands'):     # every README command: ran, or left out and why
        parts.append('<h3>The README\'s commands</h3><table><tr><th>command</th><th></th>'
                     '<th>why</th></tr>' + ''.join(
                         '<tr><td><code>%s</code>%s</td><td>%s</td><td>%s</td></tr>' % (
                             _e(c['command']), ' (in %s)' % _e(c['from']) if c.get('from')
                             else '', 'ran' if c['ran'] else 'a build step' if c.get(
                                 'kind') == 'build' else 'left out', _e(c['why']))
                         for c in main['readme_commands']) + '</table>')
    for cut in main.get('cut') or []:     # what its worker did not send back whole
        parts.append('<p>cut from what the worker sent back: %s</p>' % _e(cut))
    if summary['checks']:
        parts.append('<h2>Checks</h2><table><tr><th>check</th><th>figure</th><th>threshold</th>'
                     '<th></th><th>points</th><th>detail</th></tr>')
        for check in summary['checks']:
            css, word = report_judged.outcome(check)
            parts.append('<tr><td>%s</td><td>%s</td><td>%s</td><td class="%s">%s</td>'
                         '%s<td>%s</td></tr>' % (
                             _e(check['name']), _e(figure(check['value'], '—')),
                             _e(check['threshold']), css, word,
                             report_marks.points_cell(check),
                             report_judged.why_html(check['detail'])))
        parts.append('</table>')
    episodes = evidence.episodes_sentence(runs)
    if episodes:
        parts.append('<p>%s.</p>' % _e(episodes))
    parts += evidence.section(pictures.get('evidence'), rel)
    parts += report_judged.judged_section(main, profile['checks'])
    if pictures.get('top') or pictures.get('head'):
        parts.append('<h2>What happened</h2><p>')
        for key in ('top', 'head'):
            if pictures.get(key):
                parts.append('<img src="%s" alt="%s">' % (rel(pictures[key]), key))
        parts.append('</p>')
    parts += camera_section(pictures, rel)
    parts.append('<h2>Runs</h2><table><tr><th>run</th><th>seed</th><th>verdict</th>'
                 '<th>simulated s</th><th>real-time factor</th><th>wall s</th>'
                 '<th>peak memory MB</th><th>where</th><th>to repeat it by hand</th></tr>')
    for run in runs:
        truth = run.get('truth') or {}
        rtf = run.get('real_time_factor')
        parts.append('<tr><td>%s</td><td>%s</td><td>%s</td><td>%.1f</td><td>%s%s</td>'
                     '<td>%.0f</td><td>%.0f</td><td>%s</td><td><code>%s</code></td></tr>' % (
                         _e(run['label']), _e(run.get('seed')), _verdict_badge(run['verdict']),
                         truth.get('sim_time', 0.0), '%.2f' % rtf if rtf else '—',
                         ' (below 0.95: starved)' if rtf and rtf < 0.95 * (
                             run.get('real_time_factor_asked') or 1) else '',
                         run.get('wall_time', 0.0), run.get('peak_memory_mb') or 0,
                         _e(' then '.join(run.get('workers') or [])),
                         _e(run.get('repeat_command'))))
    parts.append('</table>')
    errors = main.get('errors') or []
    parts.extend(report_failures.launch_errors_section(main))
    parts.extend(report_failures.deaths_section(main))
    parts.extend(report_failures.keyboard_section(main))
    if errors:
        parts.append('<h2>Errors (%d)</h2>' % main.get('error_count', len(errors)))
        for error in errors[:10]:
            parts.append('<p>%s, line %s</p><pre>%s</pre>' % (_e(error['source']),
                                                             _e(error['line']),
                                                             _e(error['excerpt'])))
    work = os.path.join(runs_dir, main['label'], 'work')
    if main['verdict'] in ('not_built', 'grader_error', 'not_started'):
        for name in ('build.log',) + tuple('command-%d.log' % i
                                           for i in range(len(main.get('commands') or []))):
            text = read_log(work, os.path.join('logs', name), {})
            if text:
                parts.append('<h2>%s</h2><pre>%s</pre>' % (_e(name), _e(text[-20000:])))
    parts.append('<p>Package version %s. Records: <code>%s</code></p></body></html>'
                 % (_e(main.get('version', '?')), _e(os.path.join(runs_dir, main['label']))))
    return ''.join(parts)


def _index(summaries, pictures, profile, title):
    check_names = [c['name'] for c in profile['checks']]
    counts = collections.Counter(s['verdict'] for s in summaries.values())
    parts = [head(title, STYLE, SORT_JS + IMAGES_JS),
             '<h1>%s</h1><p>%d submissions: %s. Click a heading to sort.</p>' % (
                 _e(title), len(summaries),
                 ', '.join('%d %s' % (counts[v], v) for v in VERDICTS if counts[v])),
             report_marks.histogram_svg(summaries),
             '<table><thead><tr><th onclick="sortBy(this)">submission</th>'
             '<th onclick="sortBy(this)">score</th><th onclick="sortBy(this)">verdict</th>']
    parts += ['<th onclick="sortBy(this)">%s</th>' % _e(n) for n in check_names]
    parts.append('<th onclick="sortBy(this)">first error</th><th>picture</th></tr></thead><tbody>')
    for s in report_marks.by_score(summaries):
        name, values = s['name'], {c['name']: c for c in s['checks']}
        parts.append('<tr><td><a href="pages/%s.html">%s</a></td>%s<td data-key="%d">%s%s</td>' % (
            _e(name), _e(name), report_marks.score_cell(s), VERDICTS.index(s['verdict']),
            _verdict_badge(s['verdict']),
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


def write(report_dir, profile, title=None):
    """Make the report from ``report_dir/runs``; returns the summaries."""
    runs_dir = os.path.join(report_dir, 'runs')
    every = load_runs(runs_dir)
    runs, tried = report_releases.counted(every, profile)   # in several releases: the better
    summaries = report_marks.add_scores(summarise(runs), runs, profile)
    for name, summary in summaries.items():
        summary['releases'] = tried.get(name) or []
    pages = os.path.join(report_dir, 'pages')
    img_dir = os.path.join(pages, 'img')
    shutil.rmtree(pages, ignore_errors=True)
    os.makedirs(img_dir)
    pictures = {}
    for name, summary in summaries.items():
        group = [r for r in runs if r['name'] == name]
        main = next(r for r in group if r['label'] == summary['main_run'])
        pictures[name] = _run_pictures(main, runs_dir, img_dir, profile)
        with open(os.path.join(pages, name + '.html'), 'w') as f:
            f.write(_page(summary, group, runs_dir, pictures[name], profile))
    feedback.write_all(report_dir, summaries, runs, pictures, profile)      # the students'
    gradescope.write_all(report_dir, summaries, runs, profile)
    title = title or 'Grading: %s' % (profile.get('title') or profile['name'])
    with open(os.path.join(report_dir, 'index.html'), 'w') as f:
        f.write(_index(summaries, pictures, profile, title))
    with open(os.path.join(report_dir, 'report.json'), 'w') as f:
        json.dump({'profile': profile, 'submissions': list(summaries.values()), 'runs': every},
                  f, indent=1, default=str)
    report_marks.write_csv(os.path.join(report_dir, 'grades.csv'), summaries, profile)
    # the index's column of each one's highest pair, when a similarity report is there
    from exp_assignment2.grading.similarity.page import annotate_index
    annotate_index(report_dir)
    return summaries

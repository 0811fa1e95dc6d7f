"""The teacher's page of each submission (no ROS): ``pages/<name>.html``, the
commands and where they came from, the verdict, the checks and what was
judged, the arena from above, the head's angle, the camera's and the
student's windows' frames, each run, the nodes that died, the errors and the
logs; made from the runs' records only (:mod:`~exp_assignment2.grading.report.index`
writes them)."""
import os
import shutil

from exp_assignment2.grading import record
from exp_assignment2.grading.judge import metrics
from exp_assignment2.grading.judge import roles as roles_
from exp_assignment2.grading.judge.logs import read_log
from exp_assignment2.grading.report import commits as report_commits
from exp_assignment2.grading.report import evidence
from exp_assignment2.grading.report import failures as report_failures
from exp_assignment2.grading.report import figures
from exp_assignment2.grading.report import judged as report_judged
from exp_assignment2.grading.report import marks as report_marks
from exp_assignment2.grading.report import packages as report_packages
from exp_assignment2.grading.report import releases as report_releases
from exp_assignment2.grading.report import starts as report_starts
from exp_assignment2.grading.report.camera import camera_section, window_pictures
from exp_assignment2.grading.report.html import IMAGES_JS, e as _e, figure, head

COLOURS = {'passed': '#2e7d32', 'failed_checks': '#ef6c00', 'crashed': '#c62828',
           'timed_out': '#6a1b9a', 'not_started': '#ad1457', 'not_built': '#4e342e',
           'grader_error': '#546e7a'}
STYLE = '''th{cursor:pointer}.v{color:#fff;padding:2px 6px;
border-radius:3px;white-space:nowrap}.frames img{margin-right:6px}.frames
img.window{max-width:760px} .flaky{background:#fff3cd;padding:1px 4px}
.nj{font-style:italic}'''
def verdict_badge(verdict, pending=0):
    """The verdict, and the points a person must still mark (checks not judged)."""
    return '<span class="v" style="background:%s">%s</span>%s' % (
        COLOURS.get(verdict, '#333'), verdict,
        ' <span class="nj">%s points to mark by hand</span>' % report_marks._number(pending)
        if pending else '')


def pictures(run, runs_dir, img_dir, profile):
    """The run's figures and chosen frames, copied next to its page."""
    record_dir = os.path.join(runs_dir, run['label'], 'record')
    trace = metrics.Trace.from_record(record_dir)
    roles = roles_.of_run(run, trace, profile)
    label = run['label']
    pictures = {}
    shown = evidence.pictures(record_dir, trace, roles, run, img_dir)     # the checks' moments
    pictures['evidence'] = shown
    top = figures.top_view(trace, roles, os.path.join(img_dir, label + '_top.png'),
                           marks=[(m[0], m[2]) for m in shown['moments']])
    if top:
        pictures['top'] = top
    head = figures.head_angle(trace, roles, os.path.join(img_dir, label + '_head.png'))
    if head:
        pictures['head'] = head
    frames, times = {}, {}
    for moment, source in figures.chosen_frames(record_dir, trace, roles).items():
        target = os.path.join(img_dir, '%s_%s.jpg' % (label, moment.replace(' ', '_')))
        shutil.copy(source, target)
        frames[moment], times[moment] = target, figures.frame_time(source)
    pictures['frames'] = frames
    pictures['windows'] = window_pictures(label, runs_dir, img_dir, record_dir, times)
    thumb_source = frames.get('closest approach') or frames.get('end') or top
    if thumb_source:
        thumb = figures.thumbnail(thumb_source, os.path.join(img_dir, label + '_thumb.jpg'))
        if thumb:
            pictures['thumb'] = thumb
    return pictures


def page(summary, runs, runs_dir, pictures, profile):
    main = next(r for r in runs if r['label'] == summary['main_run'])
    rel = lambda p: 'img/' + os.path.basename(p)   # noqa: E731
    parts = [head(summary['name'], STYLE, IMAGES_JS),
             '<p><a href="../index.html">&larr; all submissions</a></p>',
             '<h1>%s %s</h1>' % (_e(summary['name']), verdict_badge(summary['verdict'],
                                                                    summary.get('pending'))),
             '<p>%s</p>' % _e(summary['reason']), report_marks.score_paragraph(summary)]
    if summary['flaky']:
        parts.append('<p class="flaky">flaky: the repeats ended %s</p>'
                     % _e(', '.join(summary['verdicts'])))
    parts.append('<h2>Started with</h2><p>from %s</p>%s' % (
        _e(main.get('commands_from')), report_starts.table(main)))
    parts += report_commits.section(summary)
    for note in record.notes(main):
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
    for cut in record.teacher(main, 'cut'):     # what its worker did not send back whole
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
                         _e(run['label']), _e(run.get('seed')), verdict_badge(run['verdict']),
                         truth.get('sim_time', 0.0), '%.2f' % rtf if rtf else '—',
                         ' (below 0.95: starved)' if rtf and rtf < 0.95 * (
                             run.get('real_time_factor_asked') or 1) else '',
                         run.get('wall_time', 0.0), run.get('peak_memory_mb') or 0,
                         _e(' then '.join(record.teacher(run, 'workers'))),
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

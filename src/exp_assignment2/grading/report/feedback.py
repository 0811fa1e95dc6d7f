"""The student's page (no ROS): ``REPORT/feedback/<name>.html``, one self-contained
file a teacher can send or upload (its pictures inlined as ``data:`` URIs).

It holds the score, each check the student may see (a check of the profile
with ``visibility: hidden`` is left out, and so are its points and its name
in the verdict's reason), what to fix in plain words (the build's first
error, the command that did not start, the node that died and why, the first
traceback, the checks that failed) and the run's pictures; nothing of another
submission, and no absolute path of the teacher's machine (:func:`cleaner`).
"""
import base64
import os
import re

from exp_assignment2.grading.report import commits
from exp_assignment2.grading.report import evidence
from exp_assignment2.grading.report import failures as report_failures
from exp_assignment2.grading.report import judged as report_judged
from exp_assignment2.grading.report import packages as report_packages
from exp_assignment2.grading.report import releases as report_releases
from exp_assignment2.grading.report import starts as report_starts
from exp_assignment2.grading.judge import verdicts
from exp_assignment2.grading.report.marks import _number
from exp_assignment2.grading.report.html import e as _e, figure, head

WORDS = {
    'passed': 'Your package ran and did everything the checks look for.',
    'failed_checks': 'Your package ran, but some checks were not met.',
    'crashed': 'Your package ran, then it ended before the end of the run (a required node '
               'died, or every command had ended, or it broke a limit) before its checks '
               'were met. Its checks were judged on what the robot did until then, and keep '
               'the points they earned.',
    'timed_out': 'Your package did not finish in time. Its checks were judged on what the '
                 'robot did until then, and keep the points they earned.',
    'not_started': 'Your package was built, but a command that starts it did not start: '
                   'nothing of it could be judged.',
    'not_built': 'Your package did not build: nothing of it could be judged.',
    'grader_error': 'The grader failed on its own side (not because of your code). Your '
                    'submission has no score yet: it will be graded again.',
}
NOT_JUDGED = ('The grader could not judge some checks (it could not tell which part of your '
              'robot or world they are about): your teacher marks those by hand.')


def words(summary):
    """What the verdict means for the student, in a sentence or two."""
    if summary['verdict'] == 'passed' and summary.get('pending'):
        return 'Your package ran and met every check the grader could judge. ' + NOT_JUDGED
    said = WORDS.get(summary['verdict'], '')
    return said + (' ' + NOT_JUDGED if summary.get('pending') else '')
RUN_PATH = re.compile(r'(/[^\s"\'<>:]*)?/runs/[^/\s"\']+/work/(overlay/[^/\s"\']+/)?(src/)?')
STYLE = 'body{max-width:60em}img{max-width:100%}.score{font-size:1.6em}'


def cleaner(report_dir, run):
    """A function that takes the teacher's absolute paths out of a text: the
    run's package and work directories, the report, the submission's folder
    and the home directory."""
    work = os.path.join(report_dir, 'runs', run['label'], 'work')
    pairs = [(os.path.join(work, 'src') + '/', ''), (work + '/', ''), (work, '.')]
    for token in (run.get('repeat_command') or '').split():
        if token.startswith('/') and token.rstrip('/').count('/') >= 2:
            pairs.append((os.path.dirname(token.rstrip('/')) + '/', ''))
    for where in (report_dir, os.path.expanduser('~')):
        pairs += [(where + '/', ''), (where, '.')]
    pairs += [(os.path.realpath(a), b) for a, b in pairs if os.path.realpath(a) != a]
    pairs.sort(key=lambda p: -len(p[0]))

    def clean(text):
        # a run's own directory as the sandbox named it (e.g. /tmp/exp2-grade-*/runs/L/work/
        # overlay/L-hash/src/): the package's path from its folder on
        text = RUN_PATH.sub('', str(text if text is not None else ''))
        for old, new in pairs:
            if len(old.strip('/')) > 1:
                text = text.replace(old, new)
        return text
    return clean


def _inline(path):
    if not path or not os.path.isfile(path):
        return ''
    kind = 'image/png' if path.endswith('.png') else 'image/jpeg'
    with open(path, 'rb') as f:
        return 'data:%s;base64,%s' % (kind, base64.b64encode(f.read()).decode('ascii'))


def visible_checks(summary):
    return [c for c in summary['checks'] if c.get('visibility', 'visible') != 'hidden']


def to_fix(summary, run, clean):
    """[plain-words item (HTML)] of what the student should fix, the first first."""
    items, verdict = [], summary['verdict']
    if verdict == 'grader_error':
        return ['Nothing: the fault was the grader\'s. Your submission will be graded again.']
    if verdict in ('not_built', 'not_started'):
        items.append('%s: <code>%s</code>' % (
            'The build failed' if verdict == 'not_built' else 'This command started nothing',
            _e(clean(summary['reason']))))
    for c in run.get('readme_commands') or []:
        if not c.get('ran') and c.get('kind') != 'build':     # the grader builds: no fault
            items.append('Your README\'s command <code>%s</code> was not run: %s' % (
                _e(clean(c['command'])), _e(clean(c.get('why')))))
        elif c.get('corrected'):        # it names what the package does not have
            items.append('Your README\'s command <code>%s</code> names what your package does '
                         'not have: %s' % (_e(clean(c['command'])), _e(clean(c.get('why')))))
    for e in run.get('launch_errors') or []:
        items.append('roslaunch could not start a node (<code>%s</code>): %s' % (
            _e(clean(e.get('command'))), _e(clean(e.get('line')))))
    errors = run.get('errors') or []
    for d in run.get('died') or []:
        said = '' if d.get('abort') else verdicts.why_it_died(errors, d)
        did = report_failures.how_it_ended(d)
        items.append('The node <code>%s</code> died (exit code %s%s)%s' % (
            _e(d['node']), _e(d.get('exit', d.get('code'))), '; ' + _e(did) if did else '',
            ': <pre>%s</pre>' % _e(clean(d['abort'])) if d.get('abort') else
            ': <b>%s</b>' % _e(clean(said)) if said else ''))
    if errors:
        first = errors[0]
        items.append('The first Python error (of %d), in %s line %s: <b>%s</b><pre>%s</pre>' % (
            run.get('error_count', len(errors)), _e(clean(first['source'])), _e(first['line']),
            _e(clean(first['summary'])), _e(clean(first['excerpt']))))
    for check in visible_checks(summary):
        if check['passed'] is False:
            items.append('The check &ldquo;%s&rdquo; needs %s; your run gave %s (%s).' % (
                _e(check['name']), _e(check['threshold']), _e(figure(check['value'])),
                _e(clean(check['detail']))))
    return items


def _score_part(summary):
    shown = visible_checks(summary)
    hidden = len(summary['checks']) != len(shown) or any(
        c.get('visibility') == 'hidden' for c in summary.get('score_checks') or [])
    if summary.get('score') is None:
        return '<p class="score">No score yet</p>'
    by_hand = ('<p>%s points are for your teacher to mark by hand: the grader could not '
               'judge those checks (see below).</p>' % _number(summary['pending'])
               if summary.get('pending') else '')
    if not hidden:
        return '<p class="score">Score: <b>%s</b> / %s</p>%s' % (
            _number(summary['score']), _number(summary['max']), by_hand)
    got = [c for c in summary.get('score_checks') or [] if c.get('visibility') != 'hidden']
    return ('<p class="score">Points from the checks shown here: <b>%s</b> / %s</p><p>Your '
            'teacher grades further checks that are not shown here.</p>' % (
                _number(sum(c['points'] or 0 for c in got)),
                _number(sum(c['max_points'] for c in got))))


def page(summary, run, pictures, profile, clean):
    """The student's page (a string of HTML)."""
    parts = [head('Feedback: %s' % summary['name'], STYLE),
             '<h1>Feedback: %s</h1><p>%s</p>' % (_e(summary['name']),
                                                 _e(profile.get('title') or profile['name'])),
             _score_part(summary), '<p>%s</p>' % _e(words(summary))]
    if commits.line(summary):       # a git repository: the commit graded, days late
        parts.append('<p>%s</p>' % _e(commits.line(summary)))
    fix = to_fix(summary, run, clean)
    if fix:
        parts.append('<h2>What to fix</h2><ol>%s</ol>' % ''.join('<li>%s</li>' % i for i in fix))
    shown = visible_checks(summary)
    if shown:
        parts.append('<h2>Checks</h2><table><tr><th>check</th><th>your figure</th>'
                     '<th>needed</th><th></th><th>points</th><th>detail</th></tr>')
        for c in shown:
            css, word = report_judged.outcome(c)
            parts.append('<tr><td>%s</td><td>%s</td><td>%s</td><td class="%s">%s</td>'
                         '<td>%s / %s</td><td>%s</td></tr>' % (
                             _e(c['name']), _e(figure(c['value'])), _e(c['threshold']), css,
                             {'passed': 'met', 'failed': 'not met'}.get(
                                 word, 'not judged: your teacher marks it'),
                             _e(_number(c.get('points')) or '—'),
                             _e(_number(c.get('max_points'))),
                             report_judged.why_html(clean(c['detail']))))
        parts.append('</table>')
    hidden = 'hidden' in ((run.get('episode') or {}).get('visibility'), (
        (pictures.get('evidence') or {}).get('episode') or {}).get('visibility'))
    if not hidden:      # a hidden episode's seed and pictures are the teacher's
        parts += evidence.section(pictures.get('evidence'), _inline, {c['name'] for c in shown},
                                  'When each check was decided', your='your')
    parts += report_judged.judged_section(run, shown, 'What the grader judged')
    parts.append('<h2>How it was started</h2>' + report_starts.table(run, clean))
    parts += report_packages.packages_section(run, clean)
    parts += report_releases.releases_section(run, summary.get('releases'), clean)
    parts += report_failures.keyboard_section(run, clean)
    pics = [] if hidden else [(k, pictures.get(k)) for k in ('top', 'head')] + \
        list((pictures.get('frames') or {}).items())     # the moments in their order
    for title, chosen, _ in ((pictures.get('windows') or {}).get('rows') or [] if not hidden
                             else []):
        pics += [('your window "%s" at %s' % (title, m), p) for m, p in chosen.items() if p]
    pics = [(k, _inline(p)) for k, p in pics if p]
    if pics:
        parts.append('<h2>What the robot did</h2>')
        parts += ['<figure><img src="%s" alt="%s"><figcaption>%s</figcaption></figure>' % (
            uri, _e(k), _e({'top': 'the arena from above', 'head': 'the head\'s angle'}.get(
                k, 'the camera at ' + k if not k.startswith('your') else k)))
            for k, uri in pics if uri]
    parts.append('</body></html>')
    return ''.join(parts)


def write_all(report_dir, summaries, runs, pictures, profile):
    """``REPORT/feedback/<name>.html`` for each submission; [paths]."""
    folder = os.path.join(report_dir, 'feedback')
    os.makedirs(folder, exist_ok=True)
    written = []
    for name, summary in summaries.items():
        run = next((r for r in runs if r['label'] == summary.get('score_run')), None) or \
            next(r for r in runs if r['label'] == summary['main_run'])
        path = os.path.join(folder, name + '.html')
        with open(path, 'w') as f:
            f.write(page(summary, run, pictures.get(name) or {}, profile,
                         cleaner(os.path.abspath(report_dir), run)))
        written.append(path)
    return written

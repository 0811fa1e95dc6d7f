"""Gradescope (no ROS): a submission's ``results.json`` in Gradescope's documented
format (its autograder specifications: docs/grading.md, "Gradescope"), and
the autograder's entry point (``python3 -m exp_assignment2.grading.report.gradescope``,
``tools/gradescope/run_autograder``).

``grade`` writes ``REPORT/gradescope/<name>/results.json`` for every
submission: ``score``, ``execution_time``, ``output``, ``stdout_visibility``
and one test a check of the profile (``name``, ``score``, ``max_score``,
``status``, ``output``, ``visibility``: the check's). A grader error gives
no score anywhere, never 0: its ``output`` says the run must be made again
(Gradescope then has no score for it, and the teacher reruns it).

:func:`autograde` grades ``ROOT/submission`` as one submission into
``ROOT/results/results.json`` (ROOT: ``/autograder``, or ``--root``, or the
``EXP2_AUTOGRADER_ROOT`` environment variable) and always writes a results
file, even when the grader itself fails.
"""
import argparse
import glob
import html
import json
import os
import re
import shutil
import subprocess
import sys
import time

from exp_assignment2.grading.paths import REPO
from exp_assignment2.grading.report.feedback import cleaner, to_fix, words
from exp_assignment2.grading.report.html import figure

ROOT_ENV = 'EXP2_AUTOGRADER_ROOT'
ARGS_ENV = 'EXP2_AUTOGRADER_ARGS'      # more arguments of grade, e.g. "--profile miro"


def _text(item_html):
    """Plain text of one of the feedback page's items."""
    text = re.sub(r'<pre>', '\n', item_html)
    return html.unescape(re.sub(r'<[^>]+>', '', text)).strip()


def _test_output(check, clean):
    value = check['value']
    shown = figure(value)
    if check['passed'] is None:          # a role it needs could not be told: a person marks it
        return 'not judged by the grader; your teacher marks it by hand (%s)' % clean(
            check.get('detail') or '')
    return '%s: %s (needed %s)%s' % ('met' if check['passed'] else 'not met', shown,
                                     check['threshold'],
                                     '; ' + clean(check['detail']) if check.get('detail') else '')


def results(summary, run, profile, clean, execution_time=None):
    """Gradescope's results.json (a dict) for one submission's summary."""
    no_score = summary.get('score') is None
    lines = [words(summary)]
    fixes = [_text(i) for i in to_fix(summary, run, clean)]
    if fixes:
        lines += ['', 'What to fix:'] + ['%d. %s' % (i + 1, f) for i, f in enumerate(fixes)]
    checks = {c['name']: c for c in summary['checks']}
    tests = []
    for i, marks in enumerate(summary.get('score_checks') or []):
        check = checks.get(marks['name'])
        test = {'name': marks['name'], 'number': str(i + 1), 'max_score': marks['max_points'],
                'visibility': marks.get('visibility', 'visible'),
                'output': _test_output(check, clean) if check else
                'not judged: %s' % summary['verdict'].replace('_', ' ')}
        if not no_score and not marks.get('pending'):    # a pending one: no score, not a 0
            test['score'] = marks['points'] or 0.0
            test['status'] = 'passed' if check and check['passed'] else 'failed'
        tests.append(test)
    out = {'output': '\n'.join(lines).strip(), 'stdout_visibility': 'hidden', 'tests': tests}
    if execution_time is not None:
        out['execution_time'] = int(round(execution_time))
    if no_score:
        out['output'] = ('NOT GRADED: the grader failed on its own side (%s). This is not a '
                         'score of 0: the submission must be graded again.\n\n' %
                         clean(summary.get('reason') or 'grader error')) + out['output']
    else:
        out['score'] = summary['score']
    return out


def write_all(report_dir, summaries, runs, profile):
    """``REPORT/gradescope/<name>/results.json`` of every submission; [paths]."""
    written = []
    for name, summary in summaries.items():
        run = next((r for r in runs if r['label'] == summary.get('score_run')), None) or \
            next(r for r in runs if r['label'] == summary['main_run'])
        folder = os.path.join(report_dir, 'gradescope', name)
        os.makedirs(folder, exist_ok=True)
        took = sum(r.get('wall_time') or 0 for r in runs if r['name'] == name)
        path = os.path.join(folder, 'results.json')
        with open(path, 'w') as f:
            json.dump(results(summary, run, profile, cleaner(os.path.abspath(report_dir), run),
                              took), f, indent=1)
        written.append(path)
    return written


def grader_failed(why, execution_time=None):
    """The results.json of an autograder that could not grade: no score, never 0."""
    out = {'output': 'NOT GRADED: the grader failed on its own side (%s). This is not a '
                     'score of 0: the submission must be graded again.' % why,
           'stdout_visibility': 'hidden', 'tests': []}
    if execution_time is not None:
        out['execution_time'] = int(round(execution_time))
    return out


def autograde(root, grade_command, extra_args=(), log=print):
    """Grade ``root/submission`` into ``root/results/results.json``; the results (a dict)."""
    started = time.time()
    results_dir = os.path.join(root, 'results')
    os.makedirs(results_dir, exist_ok=True)
    out = os.path.join(results_dir, 'grading-report')
    target = os.path.join(results_dir, 'results.json')
    shutil.rmtree(out, ignore_errors=True)      # a result of an earlier grading is not this one's
    try:
        proc = subprocess.run(list(grade_command) + [os.path.join(root, 'submission'), '--out',
                                                     out] + list(extra_args))
        found = sorted(glob.glob(os.path.join(out, 'gradescope', '*', 'results.json')))
        if len(found) != 1:
            raise RuntimeError('grade exited with %s and wrote %d results for one submission'
                               % (proc.returncode, len(found)))
        with open(found[0]) as f:
            data = json.load(f)
        name = os.path.basename(os.path.dirname(found[0]))
        page = os.path.join(out, 'feedback', name + '.html')
        if os.path.isfile(page):       # kept beside results.json for the teacher
            shutil.copy(page, os.path.join(results_dir, 'feedback.html'))
    except Exception as exc:            # noqa: BLE001 -- always a results file
        log('the grader failed: %s' % exc)
        data = grader_failed(str(exc)[:300] or type(exc).__name__, time.time() - started)
    with open(target + '.tmp', 'w') as f:
        json.dump(data, f, indent=1)
    os.replace(target + '.tmp', target)
    return data


def main(argv=None):
    parser = argparse.ArgumentParser(description='Gradescope\'s autograder: grades '
                                     'ROOT/submission into ROOT/results/results.json')
    parser.add_argument('--root', default=os.environ.get(ROOT_ENV, '/autograder'))
    parser.add_argument('grade_args', nargs='*', help='more arguments of grade (after --)')
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    extra = args.grade_args or os.environ.get(ARGS_ENV, '').split()
    data = autograde(os.path.abspath(args.root), ['bash', os.path.join(REPO, 'tools', 'run'),
                                                  'grade'], extra,
                     log=lambda t: print('[autograder] ' + t, file=sys.stderr, flush=True))
    print('[autograder] score: %s' % data.get('score', 'none (not graded)'), file=sys.stderr)
    return 0


if __name__ == '__main__':
    sys.exit(main())

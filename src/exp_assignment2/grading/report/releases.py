"""The ROS release each submission ran in, on its pages (no ROS): of a
submission run in several releases (its checks failed in the first), the
runs of the better one count (:func:`counted`), and the page shows each
release tried, its verdict and score, and why (:mod:`~exp_assignment2.grading.plan.ros_release`);
of one whose failure showed nothing of its release, why the next was not tried."""

from exp_assignment2.grading.plan import ros_release
from exp_assignment2.grading.judge import scores
from exp_assignment2.grading.report.html import e as _e


def counted(runs, profile):
    """(the runs that count, {name: [{release, verdict, score, why, counted}]}
    for the submissions run in more than one release)."""
    by_name = {}
    for run in runs:
        by_name.setdefault(run['name'], []).append(run)
    kept, tried = [], {}

    def score(run):
        return scores.run_score(run, profile)['score']
    for name, group in by_name.items():
        mine, others = ros_release.counted(group, score)
        kept.extend(mine)
        if others:
            seen = []
            for run in group:
                if run.get('release') not in [t['release'] for t in seen]:
                    seen.append({'release': run.get('release'), 'verdict': run['verdict'],
                                 'score': score(run), 'why': run.get('release_why') or '',
                                 'counted': run in mine})
            tried[name] = seen
    return [r for r in runs if r in kept], tried


def releases_section(run, tried, clean=str):
    """[HTML]: the release the counted run ran in and why; every release tried."""
    if not run.get('release'):
        return []
    parts = ['<p>ROS release: <b>%s</b> (%s)</p>' % (_e(run['release']),
                                                    _e(clean(run.get('release_why'))))]
    decision = (run.get('teacher') or {}).get('release_next') or {}
    if decision and not decision.get('tried'):
        parts.append('<p>Not run again in ROS %s, the next the course allows: %s</p>' % (
            _e(decision.get('release')), _e(clean(decision.get('why')))))
    if tried:
        parts.append('<table><tr><th>ROS release tried</th><th>verdict</th><th>score</th>'
                     '<th>why</th><th></th></tr>%s</table>' % ''.join(
                         '<tr><td>%s</td><td>%s</td><td>%s</td><td>%s</td><td>%s</td></tr>' % (
                             _e(t['release']), _e(t['verdict']),
                             _e('%g' % t['score'] if t['score'] is not None else 'no score'),
                             _e(clean(t['why'])), 'counts (the better)' if t['counted'] else '')
                         for t in tried))
    return parts

"""The commit a git repository was graded at, on the pages, and the late
policy's points off its score (no ROS).

The facts were decided before any run (:func:`~exp_assignment2.grading.plan.
git_entries.choose`) and kept in every run's record (``git``), so the report
made again (``--report-only``) says and scores the same: the commit, its
date and subject, how it was chosen, the deadline, the commits after it (not
graded), and the days late with the points off when the teacher graded a
later commit on purpose.
"""
from exp_assignment2.grading.entry.git_entries import summary as in_words
from exp_assignment2.grading.report.html import e


def facts_of(runs, name):
    """The ``git`` facts of a submission's runs (None: not a git repository)."""
    return next((r['git'] for r in runs if r['name'] == name and r.get('git')), None)


def apply_late(summaries, runs):
    """Each summary's ``git`` facts, and the late policy's points taken off
    its score (never below 0; no score stays none): ``score_before_late``
    keeps what the checks earned."""
    for name, summary in summaries.items():
        git = summary['git'] = facts_of(runs, name)
        points = (git or {}).get('late_points') or 0
        if not points or summary.get('score') is None:
            continue
        summary['score_before_late'] = summary['score']
        summary['score'] = max(0.0, summary['score'] - points)
        late = '%g points off: %d day%s late' % (points, git['late_days'],
                                                 's' if git['late_days'] > 1 else '')
        summary['score_why'] = '; '.join(w for w in (summary.get('score_why'), late) if w)
    return summaries


def line(summary):
    """A sentence for a person ('' when the submission is no git repository)."""
    git = summary.get('git')
    if not git:
        return ''
    return 'Git repository: %s.' % in_words(git)


def section(summary):
    """The teacher's page's part: [HTML]."""
    text = line(summary)
    return ['<h2>Commit graded</h2><p>%s</p>' % e(text)] if text else []

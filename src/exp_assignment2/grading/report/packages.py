"""What a page says of a submission's packages (no ROS): each package found,
where, and whether the run built it, with why (``packages`` of a run's
record: :mod:`exp_assignment2.grading.entry.packages`). Shown when the submission
holds more than one, or the one it holds is not at its top."""
from exp_assignment2.grading.report.html import e as _e



def packages_section(run, clean=str):
    """[HTML] of the run's packages table, or nothing to say."""
    listed = run.get('packages') or []
    if not listed or len(listed) == 1 and listed[0].get('rel') in ('.', ''):
        return []
    rows = ''.join('<tr><td><code>%s</code></td><td><code>%s</code></td><td>%s</td></tr>' % (
        _e(p['name']), _e(clean(p['rel'])), _e(clean(p['why']))) for p in listed)
    return ['<h3>Packages (%d found, %d built)</h3><table><tr><th>package</th><th>where</th>'
            '<th></th></tr>%s</table>' % (len(listed), sum(1 for p in listed if p['built']),
                                          rows)]

"""A run's score from its checks and its verdict (no ROS; docs/grading.md, "Rubric").

A profile's check may carry ``points`` (what it is worth, default 0),
``zero`` (the figure that earns nothing: below ``min`` or above ``max``)
and ``visibility`` (Gradescope's: who sees it). A figure at or beyond the
threshold earns the check's points; between ``zero`` and the threshold, points
in proportion; at or past ``zero`` (or with no ``zero``, anywhere short of
the threshold, or no figure at all), none. A run's score is the sum of its
checks' points, except:

* ``not_built``, ``not_started``: 0, with the verdict's reason;
* ``crashed``, ``timed_out``: the points its checks earned from the ground
  truth recorded until the end (the verdict keeps the checks of such runs);
* ``grader_error``: no score (None): the run must be made again, it is never 0.

A check the grader could not run (a robot, head or ball it needs could not be
told: :mod:`exp_assignment2.grading.judge.roles`) earns no points and loses none:
its ``points`` are None, its points are the run's ``pending`` ones, to be
marked by hand, and the score says so.

Over repeats, a submission's score is the median (the lower middle one for an
even number, so that it is a run's and its checks' points add up to it).
"""

VISIBILITIES = ('hidden', 'after_due_date', 'after_published', 'visible')
NO_SCORE = ('grader_error',)
ZERO = ('not_built', 'not_started')
KEPT = ('crashed', 'timed_out')     # the points earned before the end; said on the page


def _ratio(value, threshold, zero):
    """Share of the points for ``value`` short of ``threshold`` (0..1)."""
    if zero is None or zero == threshold:
        return 0.0
    share = (value - zero) / float(threshold - zero)
    return max(0.0, min(1.0, share))


def check_points(spec, value):
    """Points a figure earns under a profile's check (``spec``): a float."""
    points = float(spec.get('points') or 0)
    if value is None or not points:
        return 0.0
    low, high, zero = spec.get('min'), spec.get('max'), spec.get('zero')
    if low is not None and value < low:
        return round(points * _ratio(value, low, zero if zero is not None and zero < low
                                     else None), 2)
    if high is not None and value > high:
        return round(points * _ratio(value, high, zero if zero is not None and zero > high
                                     else None), 2)
    return points


def maximum(profile):
    """The profile's total of points."""
    return float(sum(c.get('points') or 0 for c in profile['checks']))


def run_score(run, profile):
    """{'score': float or None, 'max', 'why', 'checks': [{name, points, max_points,
    visibility}]} of one run's record (its ``verdict``, ``reason``, ``checks``)."""
    verdict, top = run.get('verdict'), maximum(profile)
    specs = profile['checks']
    checks = []
    got = run.get('checks') or []
    for i, spec in enumerate(specs):
        mine = got[i] if i < len(got) and got[i]['name'] == spec['name'] else {}
        unjudged = verdict not in ZERO and mine and mine.get('passed', False) is None
        checks.append({'name': spec['name'], 'max_points': float(spec.get('points') or 0),
                       'visibility': spec.get('visibility', 'visible'),
                       'points': None if verdict in NO_SCORE or unjudged else
                       0.0 if verdict in ZERO or i >= len(got) else
                       check_points(dict(spec, **(mine.get('limits') or {})),
                                    mine.get('value'))})
        if unjudged:
            checks[-1]['pending'] = True
    if verdict in NO_SCORE:
        return {'score': None, 'max': top, 'checks': checks,
                'why': 'no score: the grader failed (%s); the run must be made again'
                       % (run.get('reason') or verdict)}
    if verdict in ZERO:
        return {'score': 0.0, 'max': top, 'checks': checks,
                'why': '%s: %s' % (verdict.replace('_', ' '), run.get('reason') or '')}
    score = round(sum(c['points'] for c in checks if c['points'] is not None), 2)
    why = ''
    if verdict in KEPT:
        why = ('%s: the points its checks earned from what the robot did until then'
               % verdict.replace('_', ' ')) if run.get('checks') else \
            '%s before the simulator reported anything: no check could earn points' % \
            verdict.replace('_', ' ')
    pending = [c for c in checks if c.get('pending')]
    out = {'score': score, 'max': top, 'checks': checks, 'why': why}
    if pending:
        out['pending'] = sum(c['max_points'] for c in pending)
        out['why'] = '; '.join(filter(None, (why, '%g points not judged by the grader (%s): '
                                             'to be marked by hand' % (out['pending'], ', '.join(
                                                 c['name'] for c in pending)))))
    return out


def median_run(scored):
    """Of [(run, run_score)], the pair whose score is the median (lower middle);
    None when no run has a score (every one a grader error)."""
    have = sorted((p for p in scored if p[1]['score'] is not None),
                  key=lambda p: p[1]['score'])
    if not have:
        return None
    return have[(len(have) - 1) // 2]


def check_spec(item, here, error):
    """Raise ``error`` (one line naming it) if a check's rubric keys are wrong."""
    if 'points' in item and (not isinstance(item['points'], (int, float))
                             or isinstance(item['points'], bool) or item['points'] < 0):
        raise error('%s: points: %r is not a non-negative number' % (here, item['points']))
    if 'visibility' in item and item['visibility'] not in VISIBILITIES:
        raise error('%s: visibility: %r is not one of %s'
                    % (here, item['visibility'], ', '.join(VISIBILITIES)))
    if 'zero' in item:
        zero = item['zero']
        if not isinstance(zero, (int, float)) or isinstance(zero, bool):
            raise error('%s: zero: %r is not a number' % (here, zero))
        if not (('min' in item and zero < item['min']) or ('max' in item and zero > item['max'])):
            raise error('%s: zero: %r must be below min or above max (the figure that earns '
                        'nothing)' % (here, zero))

"""``bash tools/run grade --calibrate [REF]`` (no ROS here): a profile whose
thresholds are a reference solution's own figures, with stated margins
(docs/grading.md, "Calibration").

REF (default: :data:`DEFAULT_REF`, the course's follower that stops at 100 px
with the assignment's three behaviours) is graded as any submission, on
``--episodes`` seeds of the course's ball (3 by default; the ball is scripted
even when the profile leaves it to the student's node, so that every
behaviour has its occasion). From its runs' ground truth
(:mod:`~exp_assignment2.grading.judge.reference`) each threshold is derived
as :func:`derive` says, printed with the figures it came from, and the
profile (``--profile``'s, these thresholds put in) is written to
``OUT/<name>.yaml`` (OUT: ``--out``, default ``./calibration``). A teacher
calibrates again after changing the world or the camera; ``--report-only``
derives the profile again from the reference's runs already in OUT.
"""
import math
import os

import yaml

from exp_assignment2.grading import record
from exp_assignment2.grading.judge import reference, roles as roles_
from exp_assignment2.grading.judge.trace import Trace
from exp_assignment2.grading.paths import PACKAGE
from exp_assignment2.grading.plan import profile_keys, profiles

DEFAULT_REF = os.path.join(PACKAGE, 'config', 'grading', 'reference', 'dog')
EPISODES = 3
MARGIN = 0.1         # the distances and durations the reference needs, + 10 %
SLACK = 0.8          # the shares it reached, less 20 %
HALF = 0.5           # what the assignment sets no number for (an angle, a sleep, places): half
WINDOW = 30.0        # s after an arrival the head is judged over, at the least
LOOK_MARGIN = 0.25   # the reference's slowest look both ways, + 25 %


def _down(value, step):
    return math.floor(value / step + 1e-9) * step


def _check(profile, metric):
    return next((c for c in profile['checks'] if c['metric'] == metric), None)


def _set(profile, metric, **values):
    check = _check(profile, metric)
    if check is not None:
        check.update({k: round(v, 3) for k, v in values.items()})


def derive(profile, traces, say):
    """The profile with thresholds from the reference's ``traces`` ([(trace, roles)]);
    ``say(line)`` for each. The first pass's distances, then its figures."""
    out = dict(profile, checks=[dict(c) for c in profile['checks']])
    shared = profile_keys.with_shared(_check(out, 'looks_both_ways') or {}, out)
    found = [reference.distances(t, r, shared) for t, r in traces]
    stops = [d for f in found for d in f['stop_distances']]
    if stops:
        out['reach'] = reference.round_up(max(stops) * (1 + MARGIN), 0.1)
        say('reach %.1f m: the reference came to rest to look around %.2f to %.2f m from '
            'the ball (%d arrivals); the largest + 10 %%' % (out['reach'], min(stops),
                                                              max(stops), len(stops)))
    sweeps = [s for f in found for s in f['sweeps']]
    if sweeps:
        angle = max(0.1, _down(min(sweeps) * HALF, 0.05))
        _set(out, 'looks_both_ways', angle=angle)
        say('head angle %.2f rad each way: the reference turned its head %.2f rad each way (at '
            'the least); half that (the assignment sets no angle)' % (angle, min(sweeps)))
    times = [s for f in found for s in f['sweep_times']]
    if times:
        window = max(WINDOW, reference.round_up(max(times) * (1 + LOOK_MARGIN), 5.0))
        _set(out, 'looks_both_ways', window=window)
        say('head judged %g s after each arrival: the reference\'s slowest look both ways took '
            '%.1f s; + 25 %%, at least %g s' % (window, max(times), WINDOW))
    per_place = [p for f in found for p in f.get('per_place', [])]
    if per_place:
        per = reference.round_up(max(per_place) / HALF, 5.0)
        _set(out, 'wanders', per=per)
        say('a place each %g s out of sight asked of a shorter run: the reference wandered to a '
            'place each %s s; twice its slowest' % (per, ', '.join('%.1f' % p for p in per_place)))
    asleep_after = [a for f in found for a in f.get('asleep_after', [])]
    if asleep_after:
        unseen = max(5.0, _down(min(asleep_after) / HALF, 5.0))
        _set(out, 'sleeps', unseen=unseen)
        say('a sleep judged where the ball was out of sight %g s at a stretch: the reference '
            'fell asleep %s s after it last saw the ball; twice the least (a dog may wander '
            'a while first), down to 5 s' % (unseen, ', '.join('%.1f' % a for a in asleep_after)))
    trailing = [d for f in found for d in f['trailing']]
    if trailing:
        follow = reference.round_up(reference.percentile(trailing, 0.75) * (1 + MARGIN), 0.5)
        _set(out, 'follows_ball', follow=follow)
        say('follow %.1f m: the reference kept within %.2f m of the moving ball it saw 3/4 of '
            'the time; + 10 %%' % (follow, reference.percentile(trailing, 0.75)))
    _thresholds(out, [reference.figures(t, r, out) for t, r in traces], say)
    _duration(out, traces, say)
    return out


def _values(figures, metric):
    return [f[metric] for f in figures if f.get(metric) is not None]


def _thresholds(out, figures, say):
    """The second pass: the shares, times and counts the reference reached."""
    for metric, words in (('follows_ball', 'kept within %(follow)g m of the moving ball %(got)s '
                                           'of the time'),
                          ('looks_both_ways', 'turned its head both ways at %(got)s of the '
                                              'times it came to rest at the ball')):
        got = _values(figures, metric)
        if got:
            low = max(0.05, _down(min(v for v, _ in got) * SLACK, 0.05))
            _set(out, metric, min=low, zero=0)
            said = words % dict(_check(out, metric), got=', '.join('%.2f' % v for v, _ in got))
            say('%s at least %.2f: the reference %s; its lowest - 20 %%' % (metric, low, said))
    got = _values(figures, 'gives_up_ball')
    if got:
        slowest = max(v for v, _ in got)
        limit = reference.round_up(max(slowest * 1.25, 5.0), 5.0)
        _set(out, 'gives_up_ball', max=limit, zero=2 * limit)
        say('gives up within %g s: the reference left the hidden ball after %s s; the slowest '
            '+ 25 %%' % (limit, ', '.join('%.1f' % v for v, _ in got)))
    got = _values(figures, 'sleeps')
    if got:
        least = max(1.0, _down(min(v for v, _ in got) * HALF, 1.0))
        _set(out, 'sleeps', min=least, zero=least / 2.0)
        say('sleeps %g s (judged in a run as long as the duration): the reference rested %s s '
            'at home; half the shortest (the assignment sets no time)' % (
                least, ', '.join('%.1f' % v for v, _ in got)))
    got = _values(figures, 'wanders')
    if got:
        places = max(1, int(math.floor(min(v for v, _ in got) * HALF)))
        _set(out, 'wanders', min=places, zero=0)
        say('wanders to %d places: the reference drove to %s while the ball was out of sight; '
            'half the fewest (the assignment sets no number)' % (
                places, ', '.join('%d' % v for v, _ in got)))


def _duration(out, traces, say):
    """The duration the reference needs to show every behaviour, and what hangs on it."""
    shown = [reference.shown_by(t, r, out) for t, r in traces]
    if shown and None not in shown:
        out['duration'] = reference.round_up(max(shown) * (1 + MARGIN), 10.0)
        say('duration %g s: the reference showed every behaviour (passed each check of them) '
            'in the first %s s of its runs; + 10 %%' % (out['duration'], ', '.join(
                '%.0f' % s for s in shown)))
    else:
        say('duration %g s kept: the reference did not show every behaviour in %d of its %d '
            'runs (look at its pages)' % (out['duration'], shown.count(None), len(shown)))
    _set(out, 'sleeps', occasion=out['duration'])
    got = [f for f in (reference.figures(t, r, out).get('first_approach_time')
                       for t, r in traces) if f]
    if got:
        first = reference.round_up(max(v for v, _ in got) * 1.25, 10.0)
        _set(out, 'first_approach_time', max=min(first, out['duration']),
             zero=max(out['duration'], first))
        say('first reach within %g s: the reference first reached the ball at %s s; + 25 %%'
            % (min(first, out['duration']), ', '.join('%.0f' % v for v, _ in got)))


def write(path, profile, lines, ref):
    """The calibrated profile, its derivations as the comment at its top."""
    data = {k: v for k, v in profile.items() if k not in ('ball', 'ball_script', 'teacher_named')}
    data['ball'] = profile_keys.ball_of(profile)
    head = ['# Calibrated by: bash tools/run grade --calibrate %s' % ref,
            '# (docs/grading.md, "Calibration"). Each threshold and why:'] + \
        ['#   ' + line for line in lines]
    with open(path, 'w') as f:
        f.write('\n'.join(head) + '\n')
        yaml.safe_dump(data, f, sort_keys=False, default_flow_style=None, width=100)


def main(args, grade_main, log):
    """Grade the reference with ``grade_main(argv)``, then write the profile; the exit code."""
    ref = os.path.abspath(args.calibrate or DEFAULT_REF)
    if not os.path.isdir(ref):
        log('--calibrate: %s is not a folder (a reference solution\'s package)' % ref)
        return 2
    out = os.path.abspath(args.out or 'calibration')
    try:
        profile = profiles.load(args.profile or 'dog')
    except profiles.ProfileError as exc:
        log(str(exc))
        return 2
    os.makedirs(out, exist_ok=True)
    runs_profile = dict(profile, ball_script=profile.get('ball_script') or {
        'seeds': None, 'hidden': [], 'model': None})
    path = os.path.join(out, 'reference-profile.yaml')
    write(path, runs_profile, ['the profile the reference ran under: its ball scripted'], ref)
    report = os.path.join(out, 'reference-report')
    argv = [ref, '--out', report, '--profile', path, '--seed', str(args.seed),
            '--episodes', str(args.episodes or EPISODES)]
    for option in ('duration', 'real_time_factor', 'jobs', 'scheduler'):
        if getattr(args, option, None) is not None:
            argv += ['--' + option.replace('_', '-'), str(getattr(args, option))]
    code = 0
    if args.report_only:        # the reference's runs already there: its figures again
        log('calibrating from the reference\'s runs in %s' % report)
    else:
        log('calibrating against %s: %s episodes' % (ref, args.episodes or EPISODES))
        code = grade_main(argv)
    traces = []
    for run in record.load_all(os.path.join(report, 'runs')):
        trace = Trace.from_record(os.path.join(report, 'runs', run['label'], 'record'))
        if trace.states:
            traces.append((trace, roles_.of_run(run, trace, runs_profile)))
    if not traces:
        log('calibration: no run of the reference has ground truth (grade exited %s): see %s'
            % (code, report))
        return code or 1
    lines = []

    def say(line):
        lines.append(line)
        log('calibration: ' + line)
    calibrated = derive(profile, traces, say)
    target = os.path.join(out, '%s.yaml' % profile['name'])
    write(target, calibrated, lines, ref)
    profiles.load(target)       # it loads as any profile
    log('calibrated profile: %s (the reference\'s pages: %s)' % (
        target, os.path.join(report, 'index.html')))
    return 0

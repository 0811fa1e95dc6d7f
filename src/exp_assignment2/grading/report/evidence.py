"""What each check was decided on, on the pages (no ROS): the simulated time
of its moment, the robot's camera then (the frame of the record nearest it)
and a numbered marker on the arena plot
(:func:`~exp_assignment2.grading.report.figures.top_view`); and the ball the
run met: the course's script and its seed, and how many commands of the
student's own ball node were ignored, or the student's own ball.
"""
import os
import shutil

from exp_assignment2.grading.report import figures
from exp_assignment2.grading.report.html import e as _e


def moments(run):
    """[(number, check name, at)] of the run's checks decided at a moment."""
    found = [(c['name'], c.get('at')) for c in run.get('checks') or ()
             if c.get('at') is not None]
    return [(i, name, at) for i, (name, at) in enumerate(found, 1)]


def pictures(record_dir, trace, roles, run, img_dir):
    """{'moments': [(number, name, at, frame copied next to the page or None)],
    'ball': the sentence on the run's ball or None}."""
    frames = figures.camera_frames(record_dir, roles)
    shown = []
    for number, name, at in moments(run):
        source = figures.frame_at(frames, at)
        target = None
        if source:
            target = os.path.join(img_dir, '%s_check%d.jpg' % (run['label'], number))
            shutil.copy(source, target)
        shown.append((number, name, at, target))
    return {'moments': shown, 'ball': ball_sentence(trace, roles),
            'ball_yours': ball_sentence(trace, roles, 'your'), 'episode': run.get('episode')}


def ball_sentence(trace, roles, your='the submission\'s'):
    """'the ball followed the course's script (seed 3, 200 s); the submission's ball
    node's 12 commands were ignored', from the ground truth; None without a ball."""
    ball = roles.ball.name
    facts = trace.models.get(ball) or {} if ball else {}
    script = facts.get('scripted') or (trace.hello or {}).get('ball_script')
    if not ball and not script:
        return None
    if not script:
        return 'the ball (%s) was moved by %s own nodes' % (ball, your)
    ignored = trace.counter('ignored', ball) if ball else 0
    seed = script.get('seed')
    return 'the ball followed the course\'s script (%s%s); %s' % (
        'seed %s' % seed if seed is not None else 'legs given by hand',
        ', %g s' % script['duration'] if script.get('duration') else '',
        '%s ball node\'s %d commands were ignored' % (your, ignored) if ignored else
        'nothing else moved it' if facts.get('scripted') else
        'the simulator found no ball to play it with')


def episodes_sentence(runs):
    """'3 episodes (seeds 1, 2, 3; 1 hidden): each check's figure is the median
    over them', or '' for one run."""
    eps = [r.get('episode') for r in runs if r.get('episode')]
    if len(runs) < 2 or not eps:
        return ''
    seeds = [str(e['seed']) for e in eps if e.get('seed') is not None]
    hidden = sum(e.get('visibility') == 'hidden' for e in eps)
    return '%d episodes (%s%s): each check\'s figure is the median over them, the score the ' \
        'median episode\'s' % (len(runs), 'seeds ' + ', '.join(seeds) if seeds else
                               'each its own seed', '; %d hidden' % hidden if hidden else '')


def section(shown, rel, names=None, heading='When each check was decided', your=None):
    """HTML parts: the run's ball, and the checks' moments with the camera then;
    ``names``: only those checks; ``your``: the ball's sentence for the student."""
    rows = [m for m in (shown or {}).get('moments') or () if names is None or m[1] in names]
    parts = []
    ball = (shown or {}).get('ball_yours' if your else 'ball')
    if ball:
        parts.append('<p>%s.</p>' % _e(ball[0].upper() + ball[1:]))
    if not rows:
        return parts
    parts.append('<h2>%s</h2><p>Each number is on the arena plot where the robot was at that '
                 'moment.</p><style>img.moment{width:200px}</style><table class="frames">'
                 '<tr><th>#</th><th>check</th><th>at '
                 '(simulated s)</th><th>the robot\'s camera then</th></tr>' % _e(heading))
    for number, name, at, frame in rows:
        parts.append('<tr><td>%d</td><td>%s</td><td>%.1f</td><td>%s</td></tr>' % (
            number, _e(name), at, '<img class="moment" src="%s" alt="camera at %.1f s">' % (
                rel(frame), at)
            if frame else 'no frame of its camera then'))
    parts.append('</table>')
    return parts

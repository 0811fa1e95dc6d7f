"""A submission page's camera section (no ROS): the robot's camera at the
moments the page picks (first sight of the ball, closest approach, end) and,
beside it, what each of the student's own windows showed then, named by its
title (:mod:`~exp_assignment2.grading.run.windows`). Titles are the student's text: escaped here."""
import os
import shutil

from exp_assignment2.grading.run import windows
from exp_assignment2.grading.report.html import e as _e


def window_pictures(label, runs_dir, img_dir, record, times):
    """What the run's own windows showed at the camera's moments (``times``:
    {moment: simulated s}; the last picture without them), copied next to the
    page: {'moments', 'rows': [(title, {moment: picture or None}, {moment: when
    the window opened, for a moment before it})], 'notes'};
    None without a window."""
    shown = windows.read_windows(os.path.join(runs_dir, label, 'work', 'display'))
    if not shown or not (shown['windows'] or shown['left_out_count'] or shown['notes']):
        return None
    clock = windows.read_clock(record)
    moments = dict(times) if clock else {}
    moments = moments or {'last picture': None}
    rows = []
    for i, (window, chosen, opened) in enumerate(windows.shown_at(
            shown['windows'], clock, moments, period=shown['period'] or 1.0)):
        copied = {}
        for moment, source in chosen.items():
            copied[moment] = None
            if source:
                copied[moment] = os.path.join(img_dir, '%s_window%d_%s.jpg' % (
                    label, i, moment.replace(' ', '_')))
                shutil.copy(source, copied[moment])
        rows.append((window['title'], copied, opened))
    return {'moments': list(moments), 'rows': rows, 'notes': windows.limit_notes(shown)}


def camera_section(pictures, rel):
    """The robot's camera at the chosen moments and, beside it, what each of
    the student's windows showed then, named by its title: a row a moment."""
    frames, shown = pictures.get('frames') or {}, pictures.get('windows')
    moments = list(frames) or (shown['moments'] if shown else [])
    if not moments:
        return []
    rows = (shown or {}).get('rows', [])
    parts = ['<h2>Camera and windows</h2><table class="frames"><tr><th></th>%s%s</tr>' % (
        '<th>the robot\'s camera</th>' if frames else '',
        ''.join('<th>window &ldquo;%s&rdquo;</th>' % _e(title) for title, _, _ in rows))]
    for m in moments:
        parts.append('<tr><th>%s</th>' % _e(m))
        if frames:
            parts.append('<td><img src="%s" alt="camera at %s"></td>' % (rel(frames[m]), _e(m))
                         if m in frames else '<td></td>')
        for title, chosen, opened in rows:
            if not chosen.get(m):
                parts.append('<td>not open yet</td>')
                continue
            parts.append('<td><a href="%s"><img class="window" src="%s" alt="%s at %s"></a>%s</td>'
                         % (rel(chosen[m]), rel(chosen[m]), _e(title), _e(m),
                            '<br>opened after this moment: its first picture, at %.1f s' % opened[m]
                            if m in opened else ''))
        parts.append('</tr>')
    parts.append('</table>')
    parts += ['<p>windows: %s</p>' % _e(note) for note in (shown or {}).get('notes', [])]
    return parts

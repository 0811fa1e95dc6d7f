"""How a run's commands were started, for the teacher's page and the
student's (no ROS): each command, the folder it ran in, when the plan said
and when it started, from the driver's events (:mod:`~exp_assignment2.grading.run.inside`)."""
import html

from exp_assignment2.grading.plan.starts import describe

SAID = ('started', 'exited', 'never_started')


def rows(run):
    """[{'command', 'cwd', 'planned', 'at', 'what'}] in the commands' order;
    [] when the driver started nothing (not built: the commands are all
    there is to say)."""
    commands = run.get('commands') or []
    first = {}
    for event in run.get('events') or []:
        if event.get('event') in SAID and isinstance(event.get('index'), int):
            # a command's first word: its start, or why it had none
            first.setdefault(event['index'], event)
    if not first:
        return []
    out = []
    for i, command in enumerate(commands):
        event = first.get(i) or {}
        row = {'command': command, 'cwd': event.get('cwd') or '',
               'planned': describe(event, commands) if event else '', 'at': None, 'what': ''}
        kind = event.get('event')
        if kind == 'started':
            row['at'] = event.get('at')
        elif kind == 'exited':
            row['at'] = event.get('at')
            row['what'] = 'could not start: %s' % (event.get('error') or 'rc %s' % event.get('rc'))
        elif kind == 'never_started':
            since = event.get('since') or []
            row['what'] = ('never started: its shell still waited for `%s` to end' % (
                commands[since[1]] if since[1] < len(commands) else since[1])
                if since and since[0] == 'end' else 'not started before the run ended')
        else:
            row['what'] = 'not started before the run ended'
        out.append(row)
    return out


def table(run, clean=str):
    """The HTML of :func:`rows` (``clean``: what the student's page does to
    a text); the commands alone, one a line, when there are no rows."""
    def e(text):
        return html.escape(clean(str(text)))
    found = rows(run)
    if not found:
        return '<pre>%s</pre>' % e('\n'.join(run.get('commands') or []))
    return ('<table><tr><th>#</th><th>command</th><th>folder</th><th>planned</th>'
            '<th>started (s after the master)</th></tr>' + ''.join(
                '<tr><td>%d</td><td><code>%s</code></td><td>%s</td><td>%s</td><td>%s</td></tr>'
                % (i, e(r['command']), e(r['cwd'] or '(the submission\'s folder)'),
                   e(r['planned']), '%.1f' % r['at'] if r['at'] is not None else e(r['what']))
                for i, r in enumerate(found)) + '</table>')

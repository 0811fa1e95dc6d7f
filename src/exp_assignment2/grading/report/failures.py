"""The teacher's page's sections on what failed in a run (no ROS): the nodes
roslaunch could not start, and the nodes that died, each with why."""
from exp_assignment2.grading.report.html import e as _e



def launch_errors_section(run):
    """roslaunch's nodes that could not start: errors on the page, not a verdict."""
    errors = run.get('launch_errors') or []
    if not errors:
        return []
    return ['<h2>Nodes that could not start (%d)</h2><p>roslaunch reported these and started '
            'the rest of its nodes; the verdict follows what the robot did.</p><ul>%s</ul>' % (
                len(errors), ''.join('<li><code>%s</code>: %s</li>' % (
                    _e(e.get('command')), _e(e.get('line'))) for e in errors))]


def how_it_ended(death):
    """What roslaunch did about a death, in words ('' when it ran on)."""
    if death.get('required'):
        return 'required="true": roslaunch shut its launch down'
    if death.get('restarted'):
        return 'died %d times; roslaunch restarted it %d times (respawn="true")' % (
            death.get('deaths', 1), death['restarted'])
    return ''


def deaths_section(run):
    """Each node that died: its exit (a signal named), what roslaunch did
    about it, the message of its abort, the last lines of its output and of
    its own log."""
    died = run.get('died') or []
    if not died:
        return []
    parts = ['<h2>Nodes that died (%d)</h2><p>roslaunch runs on when a node dies, unless it is '
             'required="true", and restarts one with respawn="true": so did the run.</p>'
             % len(died)]
    for d in died:
        did = how_it_ended(d)
        parts.append('<h3>%s: exit code %s%s</h3><p>said in %s</p>' % (
            _e(d['node']), _e(d.get('exit', d['code'])), ' (%s)' % _e(did) if did else '',
            _e(d['log'])))
        if d.get('abort'):
            parts.append('<p>why it aborted:</p><pre class="abort">%s</pre>' % _e(d['abort']))
        if d.get('output'):
            parts.append('<p>the last lines of its output:</p><pre>%s</pre>' % _e(d['output']))
        for own in d.get('node_logs') or []:
            parts.append('<p>the last lines of its log %s:</p><pre>%s</pre>' % (
                _e(own['log']), _e(own['tail'])))
    return parts


def keyboard_section(run, clean=str):
    """The nodes that read the keyboard while nobody typed: they waited, as on a
    terminal nobody types into (grading.yaml's ``input:`` gives them lines)."""
    waits = run.get('keyboard') or []
    if not waits:
        return []
    return ['<h2>Waited for the keyboard (%d)</h2><p>During a grading nobody types: these '
            'reads waited, as on a terminal nobody types into, and the rest ran on '
            '(<code>input:</code> in grading.yaml gives a command lines to type).</p><ul>%s</ul>'
            % (len(waits), ''.join('<li>waited for keyboard input at <code>%s</code> (%s)</li>'
                                   % (_e(clean(w['where'])), _e(clean(w['command'])))
                                   for w in waits))]

"""A start script read as its shell runs it (no ROS, nothing run): which
``roslaunch``/``rosrun`` lines it starts, from which folder, and when.

The shell reads the script line by line, in order:

* a command run directly runs at once, and the script waits for it to end
  before the next line (a ``roslaunch`` that does not end holds every line
  after it; ``roslaunch --wait`` first waits for the master, which the grader
  has started before anything);
* ``CMD &`` runs at once and the script goes on;
* a terminal opened on a command (``gnome-terminal -x sh -c "..."``,
  ``gnome-terminal -- ...``, ``xterm -e ...``, ``konsole -e ...``, each of
  several ``--tab -e``) runs that command as a shell of its own once the
  window is open, TERMINAL_OPEN seconds later, and the script goes on at
  once (a script that worked on its author's desktop did: an ``xterm``
  without ``&`` would have held it);
* ``sleep N`` waits N seconds (``s``, ``m`` suffixes as GNU sleep);
* ``cd DIR`` changes the folder of the lines after it (the caller's rule,
  :func:`~exp_assignment2.grading.plan.own_names.cd`);
* ``roscore`` is the master the grader already started; anything else
  (``source``, ``catkin_make``, ``echo``, ``export``) takes no time.

Each start found is ``{'command', 'cwd', 'after', 'since'}``: ``after``
seconds from ``since``, which is None (the script's own start) or
``('end', k)`` (the end of the k-th start found, which the shell waits for).
"""
import re

from exp_assignment2.grading.plan import shell

TERMINAL_OPEN = 2.0     # s a desktop terminal takes to open and start its command
TERMINALS = {'gnome-terminal', 'mate-terminal', 'xfce4-terminal', 'tilix', 'terminator',
             'konsole', 'xterm', 'uxterm', 'urxvt', 'rxvt', 'lxterminal',
             'x-terminal-emulator', 'kitty', 'alacritty', 'qterminal', 'guake'}
# the options that take the rest of the line as the command's words
REST_OPTIONS = {'-x', '--', '--execute'}
# the options followed by one word that is a command line (gnome-terminal -e "...")
LINE_OPTIONS = {'-e', '--command'}
ROS_TOOLS = ('roslaunch', 'rosrun')


def _duration(found):
    """Seconds of ``sleep N[smh]...`` (GNU sleep adds its arguments), 0 if unreadable."""
    total = 0.0
    for word in found[1:]:
        match = re.match(r'^(\d+(?:\.\d*)?|\.\d+)([smhd]?)$', word)
        if match:
            total += float(match.group(1)) * {'': 1, 's': 1, 'm': 60, 'h': 3600,
                                              'd': 86400}[match.group(2)]
    return total


def _terminal_commands(found):
    """The command lines a terminal line opens: one per ``-e "LINE"`` or
    ``--command=LINE`` (a tab each), or the words after ``-x``/``--``, or
    after an ``-e`` followed by a single word (``xterm -e roslaunch p a.launch``)."""
    lines, i = [], 1
    while i < len(found):
        word = found[i]
        name, eq, value = word.partition('=')
        if word in REST_OPTIONS:
            lines.append(shell.joined(found[i + 1:]))
            break
        if name in LINE_OPTIONS and eq:
            lines.append(value)
        elif word in LINE_OPTIONS and i + 1 < len(found):
            if not re.search(r'\s', found[i + 1]):
                lines.append(shell.joined(found[i + 1:]))
                break
            lines.append(found[i + 1])
            i += 1
        i += 1
    return [line for line in lines if line.strip()]


class _Reader(object):
    """One script's starts, found line by line (see the module's docstring)."""

    def __init__(self, cd):
        self.cd, self.starts = cd, []

    def shell(self, text, cwd, since, after):
        """Read the lines of one shell (the script, or a terminal's command),
        which starts ``after`` s from ``since``; its (since, after) at the end."""
        lines = re.sub(r'\\\n', ' ', text).splitlines()
        for line in lines:
            if line.lstrip().startswith('#'):
                continue
            for command, background in shell.segments(line):
                since, after, cwd = self.command(command, background, cwd, since, after)
        return since, after

    def command(self, text, background, cwd, since, after):
        found = shell.words(text)
        if not found:
            return since, after, cwd
        inner = shell.shell_script(found)
        if inner is not None:          # sh -c "...": a shell of its own, its lines in order
            end = self.shell(inner, cwd, since, after)
            return (since, after, cwd) if background else end + (cwd,)
        tool = found[0].rsplit('/', 1)[-1]
        if tool == 'sleep' and not background:
            return since, after + _duration(found), cwd
        if tool in ('cd', 'roscd'):
            return since, after, self.cd(tool, cwd, ' '.join(found[1:]))
        if tool in TERMINALS:
            for line in _terminal_commands(found):
                self.shell(line, cwd, since, after + TERMINAL_OPEN)
            return since, after, cwd
        if tool in ROS_TOOLS:
            self.starts.append({'command': text, 'cwd': cwd, 'after': after, 'since': since})
            if not background:          # the shell waits for it to end
                return ('end', len(self.starts) - 1), 0.0, cwd
        return since, after, cwd


def read(text, cwd, cd):
    """[{'command', 'cwd', 'after', 'since'}] a script's text starts, in the
    order of its lines; ``cwd``: the folder it is run from; ``cd(tool, cwd,
    target)``: the folder a ``cd``/``roscd`` goes to."""
    reader = _Reader(cd)
    reader.shell(text, cwd, None, 0.0)
    return reader.starts

"""A run's start plan: each command with when it starts and from which
folder (no ROS), made on the teacher's side (:func:`typed`,
:func:`from_teacher`, :func:`from_readme`), carried by the RunSpec and
followed by the driver inside the sandbox (:class:`Schedule`).

A start is ``{'command', 'cwd', 'after', 'since'}``: it starts ``after``
seconds from ``since``, which is

* None: the moment the master is up;
* ``['start', j]``: the moment command j was started;
* ``['end', j]``: the moment command j ended (a start script's shell waits
  for a command it runs directly; a command that could not start ends at once);

j is always an earlier command. ``cwd`` is a folder relative to the
submission's root ('' for the root). A command whose ``since`` never comes
(the shell waits for a ``roslaunch`` that does not end) is never started.
"""

ORIGIN = None


def _start(command, cwd='', after=0.0, since=ORIGIN):
    return {'command': command, 'cwd': cwd or '', 'after': float(after),
            'since': list(since) if since else None}


def typed(commands, delay, first=0):
    """The plan of commands typed one after another in separate terminals,
    ``delay`` s apart (the first at once; ``first``: the index of the
    first in the whole plan)."""
    return [_start(c) if first + i == 0 else _start(c, after=delay, since=('start', first + i - 1))
            for i, c in enumerate(commands)]


def from_teacher(commands, delay, first=0):
    """The plan of grading.yaml's commands: a line is typed ``delay`` s after
    the previous one; ``{run, after: S}`` S s after the previous started,
    ``{run, at: S}`` S s after the master; ``cwd`` its folder."""
    plan = []
    for i, command in enumerate(commands):
        index = first + i
        if isinstance(command, str):
            plan += typed([command], delay, first=index)
        elif 'at' in command:
            plan.append(_start(command['run'], command.get('cwd'), command['at']))
        else:
            after = command.get('after', delay if index else 0)
            plan.append(_start(command['run'], command.get('cwd'), after,
                               ('start', index - 1) if index else ORIGIN))
        if isinstance(command, dict) and command.get('input') is not None:
            plan[-1]['input'] = command['input']     # what a person types into it
    return plan


def from_readme(world, runs, entries, delay):
    """The plan of the profile's ``world`` commands and the README's ``runs``
    (:func:`~exp_assignment2.grading.plan.choose.choose`'s, over ``entries``:
    :func:`~exp_assignment2.grading.plan.commands.readme_entries`). The world and each command the
    README gives to type are typed ``delay`` s apart, as a person types them; a start script's
    lines start when its shell starts them, counted from the moment the script is typed. A line
    left out takes no time: what waited for it counts from its own start."""
    plan = typed(world, delay)
    final = {run['entry']: len(plan) + i for i, run in enumerate(runs)}
    scripts_run = {entries[r['entry']].get('of') for r in runs}
    anchor = (('start', len(plan) - 1), delay) if plan else (ORIGIN, 0.0)
    time = {}           # entry -> (since, after), in the plan's indices
    for index, entry in enumerate(entries):
        if 'of' in entry:
            start = entry['start']
            waited = start['since']
            if waited is None:
                since, after = time[entry['of']]
            elif waited[1] in final:
                since, after = ('end', final[waited[1]]), 0.0
            else:
                since, after = time[waited[1]]
            time[index] = (since, after + start['after'])
        elif index in final or entry['kind'] == 'script':
            time[index] = anchor
            if index in final:
                anchor = (('start', final[index]), delay)
            elif index in scripts_run:
                anchor = (anchor[0], anchor[1] + delay)
    for run in runs:
        since, after = time[run['entry']]
        plan.append(_start(run['command'], run.get('cwd'), after, since))
    return plan


def commands_of(plan):
    """The command lines of a plan, in its order."""
    return [start['command'] for start in plan]


def span(plan):
    """Seconds after the master by which every start that waits on no end is
    due (what a run waits before it may expect the simulator; a start after
    another's end is not known in advance and is not counted)."""
    at = {}
    for i, start in enumerate(plan):
        since = start.get('since')
        if since and (since[0] == 'end' or since[1] not in at):
            continue
        at[i] = (at[since[1]] if since else 0.0) + float(start.get('after') or 0.0)
    return max(at.values()) if at else 0.0


class Schedule(object):
    """When each start of a plan is due, on a clock given (the driver's
    monotonic clock; a test's hand-turned one): ``origin`` is when the master
    was up. The driver tells it what it started and what ended."""

    def __init__(self, plan, origin):
        self.plan, self.origin = plan, origin
        self.started, self.ended = {}, {}

    def _due_at(self, i):
        since = self.plan[i].get('since')
        if not since:
            base = self.origin
        else:
            base = (self.started if since[0] == 'start' else self.ended).get(since[1])
        return None if base is None else base + float(self.plan[i].get('after') or 0.0)

    def due(self, now):
        """The commands to start at ``now``, in the plan's order."""
        return [i for i in range(len(self.plan)) if i not in self.started and
                self._due_at(i) is not None and self._due_at(i) <= now]

    def next_due(self):
        """The earliest time a command not yet started is due (None: none is
        known until something ends)."""
        times = [self._due_at(i) for i in range(len(self.plan)) if i not in self.started]
        times = [t for t in times if t is not None]
        return min(times) if times else None

    def mark_started(self, i, now):
        self.started[i] = now

    def mark_ended(self, i, now):
        self.ended.setdefault(i, now)

    def never_started(self):
        return [i for i in range(len(self.plan)) if i not in self.started]


def describe(start, commands):
    """When a start was planned, in words: "at once", "5 s after `X`
    started", "after `Y` ended"."""
    since, after = start.get('since'), float(start.get('after') or 0.0)
    gap = '%g s after ' % after if after else 'as soon as '
    if not since:
        return 'at once' if not after else '%g s after the master' % after
    other = commands[since[1]] if 0 <= since[1] < len(commands) else 'command %d' % since[1]
    if since[0] == 'start':
        return ('with `%s`' % other) if not after else '%s`%s` started' % (gap, other)
    return '%s`%s` ended' % (gap, other)


POLL = 0.5      # s between two looks at the commands when nothing is due sooner


def follow(schedule, launch, poll_exits, told_exits, stop, clock):
    """The driver's loop, until ``stop`` (an Event) is set: each command
    started when it is due (``launch(i, at)``: True when it started, False
    when it could not, which ends it at once), each end noted
    (``poll_exits()``: the commands that ended since the last look), and only
    then told (``told_exits(ended)``), so that what waits on an end is
    started in the same look."""
    while not stop.is_set():
        now = clock()
        ended = poll_exits()
        for i in ended:
            schedule.mark_ended(i, now)
        due = schedule.due(now)
        while due and not stop.is_set():
            for i in due:
                schedule.mark_started(i, now)
                if not launch(i, now - schedule.origin):
                    schedule.mark_ended(i, now)
            due = schedule.due(now)
        told_exits(ended)
        soon = schedule.next_due()
        stop.wait(POLL if soon is None else min(POLL, max(0.0, soon - clock())))

"""A student's threads that never wait, found as a run runs, and given only
the CPU the rest leaves (no ROS).

A loop with no wait in it (``while not self.done: pass``, ``self.rate.sleep``
without its call) keeps a core busy, but what it uses is not what its code
needs: given less, it goes round fewer times a second and does what it did.
Counted at what it uses, a run with one costs 1.3 to 1.7 cores, and a 2-core
machine runs it alone.

A thread of a student's process that was ready to run (on a CPU, or waiting
for one: ``/proc/PID/task/TID/schedstat``) for :data:`SPINNING` of the wall
time between two looks, and on a CPU for at least :data:`SPIN_CPU` of it, spins.
It is moved into a control group of the cpu controller whose weight is
:data:`SHARES` (a session's is 1024), one group per run: it takes the CPU the
other processes leave, and the run is counted at :data:`ELASTIC` cores for it
beside what its other processes use (cpu.Pace live, admission.cost when it
ends). Another run starts beside; should the machine be busier than that
(a run falls below 0.95 of real time), the run is run again alone as any
starved one. Where no such group can be made (no cgroup v1 cpu controller,
not root) nothing moves and the run is counted at what it uses.

Only the student's processes (cpu.kind): the simulator, ROS's and the
grader's own are never moved, whatever they do.
"""
import os
import re

from exp_assignment2.grading.run import cpu
from exp_assignment2.grading.run.sandbox import GROUP_PREFIX, _own_cgroup_v1, \
    remove_stale_groups

SPINNING = 0.95     # of the wall time ready to run: the thread never waits
SPIN_CPU = 0.25     # of the wall time on a CPU: one that hardly ran is waiting on the others
ELASTIC = 0.3       # cores a spinning thread is counted at
SHARES = 256        # the group's weight against a session's 1024 (cpu.shares)


def threads(pids):
    """{tid: (pid, CPU s, ready s)} of the threads of the student's processes
    among ``pids`` (ready: on a CPU or waiting for one, since the thread began)."""
    found = {}
    for pid in pids:
        try:
            with open('/proc/%d/cmdline' % pid, 'rb') as f:
                command = f.read().replace(b'\0', b' ').decode(errors='replace')
            if cpu.kind(command) != 'student':
                continue
            tids = os.listdir('/proc/%d/task' % pid)
        except OSError:
            continue
        for tid in tids:
            try:
                with open('/proc/%d/task/%s/schedstat' % (pid, tid)) as f:
                    run_ns, wait_ns = (int(v) for v in f.read().split()[:2])
            except (OSError, ValueError):
                continue
            found[int(tid)] = (pid, run_ns / 1e9, (run_ns + wait_ns) / 1e9)
    return found


class SpinGroup(object):
    """One run's control group (cpu controller, v1) for its spinning threads."""

    def __init__(self, name):
        self.name, self.directory, self.error = name, None, None

    def add(self, tid):
        """Move thread ``tid`` in; False (and ``error`` says why) when it cannot be."""
        if self.directory is None and self.error is None:
            self._make()
        if self.directory is None:
            return False
        try:
            with open(os.path.join(self.directory, 'tasks'), 'w') as f:
                f.write(str(tid))
        except OSError as exc:
            self.error = self.error or exc.strerror or str(exc)
            return False
        return True

    def _make(self):
        parent = _own_cgroup_v1('cpu')
        if parent is None:
            self.error = 'no cgroup v1 cpu controller'
            return
        remove_stale_groups(parent)
        name = re.sub(r'[^A-Za-z0-9_]+', '_', self.name)[:40]    # a student's folder's name
        directory = os.path.join(parent, '%sspin_%s-%d-%d' % (GROUP_PREFIX, name, os.getpid(),
                                                              id(self)))
        try:
            os.makedirs(directory, exist_ok=True)
            with open(os.path.join(directory, 'cpu.shares'), 'w') as f:
                f.write(str(SHARES))
        except OSError as exc:
            self.error = exc.strerror or str(exc)
            return
        self.directory = directory

    def remove(self):
        """The group removed, once the run's processes are gone."""
        if self.directory is not None:
            try:
                os.rmdir(self.directory)
            except OSError:
                pass        # a thread still in it: the next grading's remove_stale_groups


class Spinners(object):
    """The spinning threads of one run: :meth:`look` at each of the monitor's
    looks finds them and moves them out of the others' way."""

    def __init__(self, group):
        self.group = group
        self.last, self.last_wall = None, None
        self.found = {}         # tid -> {'pid', 'command', 'thread'}: moved, counted ELASTIC

    def look(self, pids, now):
        """The threads now (:func:`threads`), after moving the new spinners."""
        table = threads(pids)
        if self.last is not None and now > self.last_wall:
            wall = now - self.last_wall
            for tid, (pid, used, ready) in table.items():
                before = self.last.get(tid)
                if tid in self.found or before is None:
                    continue
                if ready - before[2] >= SPINNING * wall and used - before[1] >= SPIN_CPU * wall \
                        and self.group.add(tid):
                    self.found[tid] = describe(pid, tid)
        self.last, self.last_wall = table, now
        return table

    def cpu_s(self, table):
        """CPU s the found spinners had used by ``table`` (:func:`threads`)."""
        return sum(table[tid][1] for tid in self.found if tid in table)

    def counted(self, table):
        """Cores the found spinners still in ``table`` are counted at."""
        return ELASTIC * sum(1 for tid in self.found if tid in table)


def describe(pid, tid):
    """What the record says of a spinning thread: its program (the first
    ``.py`` of its command, else the executable, without a path of this
    machine), its node's name (``__name:=``) and the thread's."""
    try:
        with open('/proc/%d/cmdline' % pid, 'rb') as f:
            args = f.read().decode(errors='replace').split('\0')
        with open('/proc/%d/task/%d/comm' % (pid, tid)) as f:
            thread = f.read().strip()
    except OSError:
        args, thread = [''], ''
    program = next((a for a in args if a.endswith('.py')), args[0])
    node = next((a[len('__name:='):] for a in args if a.startswith('__name:=')), '')
    return {'program': os.path.basename(program)[:100], 'node': node[:100],
            'thread': thread[:100]}


def note(threads):
    """The run's note on its spinning threads (``found``'s values)."""
    names = ', '.join('%s%s' % (t['program'], ' (node %s)' % t['node'] if t['node'] else '')
                      for t in threads)
    return ('%s looped without waiting: from then on it ran on the CPU the other processes '
            'left (its loop went round fewer times a second, as on a busier machine), and '
            'another run could start beside this one' % names)

"""Where a run's CPU went, by process, read from outside its sandbox (no ROS):
the simulator, the run's display (Xvfb and the capture of its windows), the
viewers a display makes draw (gzclient, rviz), ROS's own processes, the
student's nodes and the grader's driver, from /proc of the processes in the
run's control group."""
import os

CLOCK_TICKS = os.sysconf('SC_CLK_TCK')
# the simulator from the source tree, catkin's relay or install (devel/lib/...), gzserver
KINDS = (('simulator', ('scripts/simulator.py', 'lib/exp_assignment2/simulator.py',
                        '/gzserver')),
         ('display', ('Xvfb ', 'grading/run/display.py')),
         # windows that only show (Gazebo's client, rviz as its viewer, image viewers):
         # with a display they draw, and cost
         ('viewer', ('gzclient', 'rviz', 'rqt_image_view', 'image_view')),
         ('grader', ('grading/run/inside.py', 'bwrap ', 'prlimit ')),
         ('ROS', ('rosmaster', 'rosout', 'roslaunch', 'roscore',
                  'spawn_model', 'spawner', 'robot_state_publisher')))


def kind(command):
    for name, marks in KINDS:
        if any(mark in command for mark in marks):
            return name
    return 'student'


def snapshot(pids):
    """{kind: CPU s} and {kind: resident MB} of the processes now alive."""
    cpu, memory = {}, {}
    for pid in pids:
        try:
            with open('/proc/%d/cmdline' % pid, 'rb') as f:
                command = f.read().replace(b'\0', b' ').decode(errors='replace')
            with open('/proc/%d/stat' % pid) as f:
                fields = f.read().rsplit(')', 1)[1].split()
            with open('/proc/%d/statm' % pid) as f:
                resident = int(f.read().split()[1]) * os.sysconf('SC_PAGE_SIZE')
        except (OSError, IndexError, ValueError):
            continue
        seconds = (int(fields[11]) + int(fields[12])) / CLOCK_TICKS   # utime + stime
        name = kind(command)
        cpu[name] = round(cpu.get(name, 0.0) + seconds, 2)
        memory[name] = round(memory.get(name, 0.0) + resident / 2 ** 20, 1)
    return cpu, memory


WARM = 20.0          # simulated s before a run's pace is read: its start (roslaunch, the
                     # spawns, a node's first frames) is not what it costs from then on
LOOK = 10.0          # wall s between two looks, and simulated s a pace is read over at least


class Pace(object):
    """What a running run costs, read as it runs: the CPU s its processes used
    per simulated s since :data:`WARM` (``cost``, None until read). A
    process that ended in between takes its CPU with it: the pace is what the
    run costs from now on, not what it cost."""

    def __init__(self):
        self.base, self.last, self.cost = None, None, None

    def look(self, pids, sim, now):
        """At simulated s ``sim`` and wall ``now``: the new cost when one was read, else None."""
        if sim is None or sim < WARM or (self.last is not None and now - self.last < LOOK):
            return None
        self.last = now
        used = sum(snapshot(pids)[0].values())
        if self.base is None or used < self.base[0]:
            self.base = (used, sim)
            return None
        if sim - self.base[1] < LOOK:
            return None
        self.cost = (used - self.base[0]) / (sim - self.base[1])
        return self.cost

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

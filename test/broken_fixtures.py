"""Texts of the grader's fixture submissions that misbehave (test/grading_fixtures.py
writes them in place of the working dog's node): one raises at start, one never moves,
a C++ node that does not compile, and a hostile one that tries every escape."""

RAISES = '''#!/usr/bin/env python3
import rospy
rospy.init_node('dog')
raise RuntimeError('the dog has no legs')
'''

IDLE = '''#!/usr/bin/env python3
import rospy
rospy.init_node('dog')
rospy.spin()
'''

BROKEN_CPP = '''#include <ros/ros.h>
int main(int argc, char **argv) {
  ros::init(argc, argv, "counter")
  return 0;
}
'''

# Every escape the sandbox must stop, each tried and what happened printed:
# writing outside its directory, reading the other runs, filling the
# memory, forking without end, a gigabyte of log, killing processes by
# name; then it never exits, whatever signal it gets.
HOSTILE = r"""#!/usr/bin/env python3
import glob, os, signal, subprocess, sys, time
import rospy
rospy.init_node('dog')
here = os.path.abspath(os.path.dirname(__file__))
def report(*words):
    print(*words, flush=True)
for path in ['/tmp/../root/hostile', '/etc/hostile', '/work/hostile',
             os.path.join(here, '..', '..', '..', '..', '..', 'hostile')]:
    try:
        with open(path, 'w') as f:
            f.write('hostile')
        report('WROTE', path)
    except OSError as exc:
        report('REFUSED', path, exc.strerror)
report('OTHERS', [f for f in glob.glob('/*/*/*/*/work/src/package.xml') +
                  glob.glob('/*/*/*/*/*/work/src/package.xml') if here not in f])
if os.fork() == 0:           # the memory
    hog = []
    while True:
        hog.append(b'x' * (50 * 1024 * 1024))
if os.fork() == 0:           # forks until the run's process limit says no
    count = 0
    while True:
        try:
            if os.fork() == 0:
                time.sleep(3600)
                os._exit(0)
            count += 1
        except OSError:
            report('FORKED', count)
            break
    time.sleep(3600)
    os._exit(0)
for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGXFSZ):
    signal.signal(sig, signal.SIG_IGN)
line = 'x' * 1023 + '\n'
try:
    for _ in range(1 << 20):      # a gigabyte of log
        sys.stdout.write(line)
    report('LOGGED 1 GB')
except BaseException as exc:
    report('LOG-STOPPED', type(exc).__name__)
subprocess.run(['pkill', '-f', 'roslaunch'])
subprocess.run(['killall', 'python3'])
while True:
    time.sleep(1)
"""

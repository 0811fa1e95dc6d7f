#!/usr/bin/env python3
"""A long run of one scenario at real_time_factor 0, and what it did:

    bash tools/run soak [--scenario dog|miro] [--minutes N]

It prints the states visited and how often, the longest stay in each, each
node's memory (resident set) at the start and the end, and the count of
ERROR and WARN lines with the distinct texts (up to 10 of each). Exit code 1
when there was an ERROR line or a node died (respawned or not).
"""
import argparse
import collections
import os
import sys
import time

import rospy
from rosgraph_msgs.msg import Log
from std_msgs.msg import String

from systems import Launch, NodeStats, start_master

SCENARIOS = {
    'dog': (['sim_world.launch', 'real_time_factor:=0'], '/robot/state',
            ['/gazebo', '/state_machine', '/go_to_point_robot', '/go_to_point_ball',
             '/move_ball_around', '/human_commands', '/robot/robot_state_publisher']),
    'miro': (['miro.launch', 'real_time_factor:=0'], '/state',
             ['/gazebo', '/state_manager', '/geometry_grounding', '/robot_motion_controller',
              '/print_info', '/robot_state_publisher']),
}


def rss_mb(pid):
    try:
        with open('/proc/%d/status' % pid) as f:
            for line in f:
                if line.startswith('VmRSS'):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        return None


def wait_for_nodes(nodes, timeout=120.0):
    """The pids of ``nodes`` once all are up (or whatever is up at ``timeout``)."""
    end = time.monotonic() + timeout
    while True:
        pids = NodeStats(nodes).pids
        if len(pids) == len(nodes) or time.monotonic() > end:
            return pids
        time.sleep(0.5)


class Recorder(object):
    """States with their ROS times, and the WARN/ERROR lines of every node."""

    def __init__(self, state_topic):
        self.states, self.lines = [], collections.defaultdict(collections.Counter)
        rospy.Subscriber(state_topic, String, lambda m: self.states.append(
            (rospy.get_time(), m.data)), queue_size=100)
        rospy.Subscriber('/rosout_agg', Log, self._on_log, queue_size=1000)

    def _on_log(self, msg):
        if msg.level >= Log.WARN:
            level = 'ERROR' if msg.level >= Log.ERROR else 'WARN'
            self.lines[level]['%s: %s' % (msg.name, msg.msg[:160])] += 1

    def stays(self, end):
        """label -> (visits, longest stay in s)."""
        result = {}
        for (t, label), (t_next, _) in zip(self.states, self.states[1:] + [(end, None)]):
            visits, longest = result.get(label, (0, 0.0))
            result[label] = (visits + 1, max(longest, t_next - t))
        return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--scenario', choices=sorted(SCENARIOS), default='dog')
    parser.add_argument('--minutes', type=float, default=20.0)
    parser.add_argument('--port', type=int, default=11421)
    args = parser.parse_args(rospy.myargv()[1:])
    launch_args, state_topic, nodes = SCENARIOS[args.scenario]
    core = start_master(args.port)
    log = os.path.join(os.environ.get('ROS_HOME', '/tmp'), 'soak_%s.log' % args.scenario)
    launch = Launch(launch_args, log)
    try:
        recorder = Recorder(state_topic)
        pids = wait_for_nodes(nodes)
        start_mb = {n: rss_mb(p) for n, p in pids.items()}
        wall0, sim0 = time.monotonic(), rospy.get_time()
        time.sleep(args.minutes * 60.0)
        wall, sim = time.monotonic() - wall0, rospy.get_time() - sim0
        end_pids = NodeStats(nodes).pids
        end_mb = {n: rss_mb(p) for n, p in end_pids.items()}
        stays = recorder.stays(rospy.get_time())
    finally:
        launch.stop()
        rospy.signal_shutdown('done')
        os.killpg(core.pid, 2)
        core.wait(20)
    print('soak of %s: %.1f min wall, %.1f min simulated (x%.2f)'
          % (args.scenario, wall / 60, sim / 60, sim / wall))
    print('states (visits, longest stay):')
    for label, (visits, longest) in sorted(stays.items()):
        print('  %-12s %5d  %8.1f s' % (label, visits, longest))
    print('memory (resident, MB) at start -> end:')
    for node in nodes:
        same = pids.get(node) == end_pids.get(node)
        print('  %-30s %7s -> %7s%s' % (node, '%.1f' % start_mb[node] if start_mb.get(node)
                                          else '-', '%.1f' % end_mb[node] if end_mb.get(node)
                                          else '-', '' if same else '  (restarted or gone)'))
    for level in ('ERROR', 'WARN'):
        counter = recorder.lines[level]
        print('%s lines: %d' % (level, sum(counter.values())))
        for text, count in counter.most_common(10):
            print('  %5d x %s' % (count, text))
    died = any(pids.get(n) != end_pids.get(n) for n in nodes)
    sys.exit(1 if recorder.lines['ERROR'] or died else 0)


if __name__ == '__main__':
    main()

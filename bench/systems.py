"""Running-system figures of the benchmark: roslaunch, then measure in wall
time (wall time is what is measured here, so the waits are wall-clock)."""
import os
import re
import subprocess
import threading
import time
import xmlrpc.client

import rosgraph
import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import CompressedImage, Image

CLK_TCK = os.sysconf('SC_CLK_TCK')
FRAMES_LINE = re.compile(r': camera: (\d+ frames, \d+ missed \([\d.]+ %\))')


class Launch(object):
    """A roslaunch in its own process group, stopped on exit."""

    def __init__(self, args, log):
        self.log = open(log, 'w')
        self.proc = subprocess.Popen(['roslaunch', 'exp_assignment2'] + args, stdout=self.log,
                                     stderr=subprocess.STDOUT, start_new_session=True)

    def stop(self):
        if self.proc.poll() is None:
            os.killpg(self.proc.pid, 2)
            try:
                self.proc.wait(20)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, 9)
        self.log.close()


class NodeStats(object):
    """CPU share and peak memory of the running nodes, from /proc."""

    def __init__(self, names):
        master = rosgraph.Master('/benchmark')
        self.pids = {}
        for name in names:
            try:
                uri = master.lookupNode(name)
                self.pids[name] = xmlrpc.client.ServerProxy(uri).getPid('/benchmark')[2]
            except (rosgraph.MasterError, OSError, xmlrpc.client.Error):
                pass         # a node that is not up is left out of the table
        self.start = {n: self._cpu(p) for n, p in self.pids.items()}
        self.t0 = time.monotonic()

    @staticmethod
    def _cpu(pid):
        with open('/proc/%d/stat' % pid) as f:
            fields = f.read().rsplit(')', 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / CLK_TCK

    @staticmethod
    def _peak_mb(pid):
        with open('/proc/%d/status' % pid) as f:
            for line in f:
                if line.startswith('VmHWM'):
                    return int(line.split()[1]) / 1024.0
        return float('nan')

    def report(self):
        wall = time.monotonic() - self.t0
        return {n: dict(cpu_percent=100.0 * (self._cpu(p) - self.start[n]) / wall,
                        peak_mb=self._peak_mb(p)) for n, p in self.pids.items()}


class Probe(object):
    """Counts camera frames; pairs each servo command with the frame before it.
    ``raw``: also subscribe to the raw image (sensor_msgs/Image), as a
    cv_bridge user would."""

    def __init__(self, raw=False):
        self.frames, self.last_frame_wall, self.latencies = 0, None, []
        self.raw_frames = 0
        self.lock = threading.Lock()
        self.subs = [
            rospy.Subscriber('/robot/camera1/image_raw/compressed', CompressedImage,
                             self._on_image, queue_size=8, buff_size=2 ** 24),
            rospy.Subscriber('/robot/cmd_vel', Twist, self._on_cmd, queue_size=50)]
        if raw:
            self.subs.append(rospy.Subscriber('/robot/camera1/image_raw', Image, self._on_raw,
                                              queue_size=1, buff_size=2 ** 25))

    def _on_raw(self, _msg):
        self.raw_frames += 1

    def close(self):
        for sub in self.subs:
            sub.unregister()

    def _on_image(self, _msg):
        with self.lock:
            self.frames += 1
            self.last_frame_wall = time.monotonic()

    def _on_cmd(self, _msg):
        now = time.monotonic()
        with self.lock:
            if self.last_frame_wall is not None and now - self.last_frame_wall < 0.03:
                self.latencies.append((now - self.last_frame_wall) * 1e3)
                self.last_frame_wall = None     # one command per frame


def measure(seconds, probe):
    """Real-time factor and frames per wall second over ``seconds`` of wall time."""
    while rospy.get_time() == 0.0:
        time.sleep(0.05)
    t0, w0, f0 = rospy.get_time(), time.monotonic(), probe.frames
    time.sleep(seconds)
    wall = time.monotonic() - w0
    return dict(rtf=(rospy.get_time() - t0) / wall,
                frames_per_wall_s=(probe.frames - f0) / wall)


def run_system(args, seconds, log, node_names, warmup=5.0, raw=False):
    launch = Launch(args, log)
    probe = Probe(raw)
    try:
        time.sleep(warmup)
        stats = NodeStats(node_names)
        result = measure(seconds, probe)
        result['nodes'] = stats.report()
        if raw:
            result['raw_frames'] = probe.raw_frames
        lat = sorted(probe.latencies)
        if lat:
            result['latency_ms'] = dict(median=lat[len(lat) // 2],
                                        p95=lat[int(len(lat) * 0.95)], n=len(lat))
    finally:
        probe.close()
        launch.stop()
        time.sleep(2)
    report = state_machine_report(log)       # written as the launch stopped
    if report:
        result['state_machine_frames'] = report
    return result


def state_machine_report(log):
    """The state machine's count of the frames it saw and missed (its line at
    shutdown, 'camera: N frames, M missed (P %)'), if the log has it."""
    with open(log) as f:
        found = FRAMES_LINE.findall(f.read())
    return found[-1] if found else None


def start_master(port=11411):
    """A roscore of our own, with use_sim_time set, and this node on it."""
    os.environ['ROS_MASTER_URI'] = 'http://localhost:%d' % port
    core = subprocess.Popen(['roscore', '-p', str(port)], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        try:
            rosgraph.Master('/benchmark').getPid()
            break
        except (rosgraph.MasterError, OSError):        # not up yet
            time.sleep(0.2)
    rospy.set_param('/use_sim_time', True)
    rospy.init_node('benchmark', disable_signals=True)
    return core

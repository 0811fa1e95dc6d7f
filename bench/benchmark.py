#!/usr/bin/env python3
"""The project's benchmark: ``bash tools/run bench``. One run measures, on this machine:

1. rendering, in-process: raw ``getCameraImage`` against the bridge's own
   per-frame path (``Simulator.render`` + ``encode_frame``) for TinyRenderer
   and EGL at 200x200 (the default), 320x320 and 800x800;
2. vision: decode + detect of real camera frames;
3. the simulator node alone (roslaunch) with a 30 Hz camera subscriber at
   real_time_factor 1 and 0: real-time factor and camera frames per wall s;
4. the full scenario-A system (sim_world.launch) at real_time_factor 1: its
   real-time factor, frame-to-command latency in PLAY, and each node's CPU
   share and peak memory.

It prints a table and writes the figures as JSON (``--out``). It starts its
own roscore (port 11411) so that its probe outlives the launches it measures.
Waits here are wall-clock on purpose: wall time is what is being measured.
"""
import argparse
import datetime
import json
import os
import platform
import subprocess
import threading
import time
import xmlrpc.client

import numpy as np
import rosgraph
import rospkg
import rospy
import yaml
from geometry_msgs.msg import Twist
from sensor_msgs.msg import CompressedImage

from exp_assignment2.sim_bridge_node import encode_frame, jpeg_params
from exp_assignment2.simulator import Simulator
from exp_assignment2.vision import BallDetector, decode_jpeg
from exp_assignment2.world import parse_models

PKG = rospkg.RosPack().get_path('exp_assignment2')
CLK_TCK = os.sysconf('SC_CLK_TCK')


def cpu_model():
    with open('/proc/cpuinfo') as f:
        for line in f:
            if line.startswith('model name'):
                return line.split(':', 1)[1].strip()
    return platform.processor()


# 1. rendering ------------------------------------------------------------

def bench_render(renderer, sizes, frames=30):
    models = parse_models(yaml.safe_load(open(os.path.join(PKG, 'config', 'world_dog.yaml')))['models'])
    sim = Simulator(models, os.path.join(PKG, 'urdf'), renderer=renderer)
    params = jpeg_params(80)
    rows = []
    for size in sizes:
        view, proj = sim.camera_matrices('robot', 'camera_link', size, size, 80.0)
        sim.render_raw(size, size, view, proj)           # warm-up
        t0 = time.perf_counter()
        for _ in range(frames):
            sim.render_raw(size, size, view, proj)
        raw = (time.perf_counter() - t0) / frames * 1e3
        render_ms, encode_ms = [], []
        for _ in range(frames):
            t0 = time.perf_counter()
            rgba = sim.render('robot', 'camera_link', size, size, 80.0)
            t1 = time.perf_counter()
            encode_frame(rgba, params)
            t2 = time.perf_counter()
            render_ms.append((t1 - t0) * 1e3)
            encode_ms.append((t2 - t1) * 1e3)
        render, encode = float(np.mean(render_ms)), float(np.mean(encode_ms))
        rows.append(dict(renderer=sim.renderer_name, size=size, raw_ms=raw, render_ms=render,
                         encode_ms=encode, bridge_ms=render + encode,
                         bridge_over_raw=(render + encode) / raw,
                         frames_per_s=1e3 / (render + encode)))
    sim.close()
    return rows


# 2. vision ---------------------------------------------------------------

def bench_vision(jpegs, repeat=200):
    detector = BallDetector()
    t0 = time.perf_counter()
    found = 0
    for i in range(repeat):
        found += detector.detect(decode_jpeg(jpegs[i % len(jpegs)])) is not None
    return dict(ms=(time.perf_counter() - t0) / repeat * 1e3, frames_with_ball=found / repeat)


def grab_frames(size, n=20):
    """Real camera frames of the default scene at ``size``, encoded as the bridge does."""
    models = parse_models(yaml.safe_load(open(os.path.join(PKG, 'config', 'world_dog.yaml')))['models'])
    sim = Simulator(models, os.path.join(PKG, 'urdf'), renderer='tiny')
    frames = []
    for _ in range(n):
        sim.set_velocity('robot', 0.0, 0.0, 0.3)
        for _ in range(3):
            sim.step()
        frames.append(encode_frame(sim.render('robot', 'camera_link', size, size, 80.0),
                                   jpeg_params(80)))
    sim.close()
    return frames


# 3./4. running systems ---------------------------------------------------

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
            except Exception:
                pass
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
    """Counts camera frames, pairs each servo command with the frame before it."""

    def __init__(self):
        self.frames = 0
        self.last_frame_wall = None
        self.latencies = []
        self.lock = threading.Lock()
        rospy.Subscriber('/robot/camera1/image_raw/compressed', CompressedImage, self._on_image,
                         queue_size=1, buff_size=2 ** 22)
        rospy.Subscriber('/robot/cmd_vel', Twist, self._on_cmd, queue_size=50)

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
    while rospy.Time.now().to_sec() == 0.0:
        time.sleep(0.05)
    t0, w0, f0 = rospy.Time.now(), time.monotonic(), probe.frames
    time.sleep(seconds)
    wall = time.monotonic() - w0
    return dict(rtf=(rospy.Time.now() - t0).to_sec() / wall,
                frames_per_wall_s=(probe.frames - f0) / wall)


def run_system(args, seconds, log, node_names, warmup=5.0):
    launch = Launch(args, log)
    try:
        probe = Probe()
        time.sleep(warmup)
        stats = NodeStats(node_names)
        result = measure(seconds, probe)
        result['nodes'] = stats.report()
        lat = sorted(probe.latencies)
        if lat:
            result['latency_ms'] = dict(median=lat[len(lat) // 2],
                                        p95=lat[int(len(lat) * 0.95)], n=len(lat))
        return result
    finally:
        launch.stop()
        time.sleep(2)


# main --------------------------------------------------------------------

def table(results):
    lines = ['exp_assignment2 benchmark, %s, %s, %d cores' % (
        results['date'], results['cpu'], results['cores'])]
    lines.append('')
    lines.append('rendering (per frame; bridge = render + RGBA->BGR + JPEG encode)')
    lines.append('%-5s %5s %9s %10s %10s %10s %9s %8s' % (
        'rend', 'size', 'raw ms', 'render ms', 'encode ms', 'bridge ms', 'ratio', 'frames/s'))
    for r in results['render']:
        lines.append('%-5s %5d %9.2f %10.2f %10.2f %10.2f %9.3f %8.1f' % (
            r['renderer'], r['size'], r['raw_ms'], r['render_ms'], r['encode_ms'],
            r['bridge_ms'], r['bridge_over_raw'], r['frames_per_s']))
    lines.append('')
    for size, v in sorted(results['vision'].items()):
        lines.append('vision (decode + detect) at %sx%s: %.2f ms/frame' % (size, size, v['ms']))
    lines.append('')
    for key, label in (('sim_rtf1', 'simulator alone, real_time_factor 1, camera 30 Hz'),
                       ('sim_rtf0', 'simulator alone, real_time_factor 0, camera 30 Hz'),
                       ('system_rtf1', 'full scenario A, real_time_factor 1, camera 30 Hz')):
        r = results[key]
        lines.append('%s: real-time factor %.2f, %.1f camera frames per wall s'
                     % (label, r['rtf'], r['frames_per_wall_s']))
        if 'latency_ms' in r:
            lines.append('  frame -> /robot/cmd_vel latency: median %.1f ms, p95 %.1f ms (n=%d)'
                         % (r['latency_ms']['median'], r['latency_ms']['p95'],
                            r['latency_ms']['n']))
        for node, s in sorted(r['nodes'].items()):
            lines.append('  %-20s CPU %5.1f %%  peak memory %6.1f MB'
                         % (node, s['cpu_percent'], s['peak_mb']))
    return '\n'.join(lines)


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
        except Exception:
            time.sleep(0.2)
    rospy.set_param('/use_sim_time', True)
    rospy.init_node('benchmark', disable_signals=True)
    return core


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--out', default=os.path.join(os.path.dirname(os.path.abspath(__file__)), 'results.json'))
    parser.add_argument('--seconds', type=float, default=15.0)
    parser.add_argument('--width', type=int, default=200, help='default camera width')
    args = parser.parse_args(rospy.myargv()[1:])
    results = dict(date=datetime.date.today().isoformat(), cpu=cpu_model(),
                   cores=os.cpu_count())
    sizes = sorted({args.width, 320, 800})
    results['render'] = bench_render('tiny', sizes) + bench_render('egl', sizes)
    results['vision'] = {str(s): bench_vision(grab_frames(s)) for s in sorted({args.width, 320})}
    core = start_master()
    try:
        run_all(args, results)
    finally:
        rospy.signal_shutdown('done')
        os.killpg(core.pid, 2)
        core.wait(20)
    print(table(results))
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, 'w') as f:
        json.dump(results, f, indent=2)
    print('\nwritten: %s' % args.out)


def run_all(args, results):
    sim_args = ['simulator.launch', 'camera_width:=%d' % args.width]
    logs = os.path.join(os.environ.get('ROS_HOME', '/tmp'), 'benchmark')
    os.makedirs(logs, exist_ok=True)
    results['sim_rtf1'] = run_system(sim_args + ['real_time_factor:=1'], args.seconds,
                                     os.path.join(logs, 'sim_rtf1.log'), ['/gazebo'])
    results['sim_rtf0'] = run_system(sim_args + ['real_time_factor:=0'], args.seconds,
                                     os.path.join(logs, 'sim_rtf0.log'), ['/gazebo'])
    nodes = ['/gazebo', '/state_machine', '/go_to_point_robot', '/go_to_point_ball',
             '/move_ball_around', '/human_commands']
    results['system_rtf1'] = run_system(
        ['sim_world.launch', 'real_time_factor:=1', 'move_ball:=false',
         'sleep_probability:=0', 'camera_width:=%d' % args.width],
        args.seconds, os.path.join(logs, 'system_rtf1.log'), nodes)


if __name__ == '__main__':
    main()

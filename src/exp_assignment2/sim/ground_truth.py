"""The run's ground truth, sent by the simulator to a grader outside the
student's sandbox (no ROS here).

A grader (:mod:`exp_assignment2.grading`) listens on a Unix socket whose path
it puts in the environment (:data:`SOCKET_ENV`); the simulator, and only it,
connects and streams JSON lines as the world runs:

* ``{"kind": "hello", ...}``: once, at connection (pid, models, and
  ``ros_release``: the ROS release whose Gazebo plugins the world follows,
  :mod:`~exp_assignment2.sim.releases`; ``ball_script``: the course the
  simulator plays for the ball, :mod:`~exp_assignment2.sim.ball_setting`,
  or null);
* ``{"kind": "model", "t": T, "facts": {...}}``: each model in the world
  then, and each one spawned later, as it is
  (:func:`~exp_assignment2.sim.model_facts.describe`: its joints, sensors,
  plugins and the topics they take commands on, whether it is a sphere, the
  ROS release it runs as, ``scripted``: the ball script moving it, its seed,
  start time and legs, else null), and
  ``{"kind": "deleted", "t": T, "name": ...}``: what the grader tells the
  robot, its head and the ball by, whatever they are called;
* ``{"kind": "state", "t": T, "models": {name: [x, y, z, yaw]},
  "joints": {model: {joint: position}}, "fed": {model: n},
  "placed": {model: n}, "ignored": {model: n}}``: every ``period`` s of
  simulated time (10 Hz by default), from the engine's own bodies: a node
  publishing a fake ``/odom`` changes nothing here. ``fed`` counts the
  commands a model's drive plugins have taken so far, ``placed`` the times a
  command put it somewhere (``set_model_state``, ``set_link_state``),
  ``ignored`` both of these sent to a model a ball script holds (which
  counts them there only), each only where not 0;
* ``{"kind": "frame", "t": T, "camera": name, "jpeg": BASE64}``: a camera's
  picture, small, at most once per ``frame_period`` s of simulated time,
  while somebody watches that camera (the frame is drawn anyway then);
* ``{"kind": "topic", "t": T, "topic": ..., "msg": {...}}``: messages of the
  topics the grader asked for (what was commanded, e.g. MiRo's targets); a
  relative name is relayed under each model's namespace (``cmd_vel``:
  ``/robot2/cmd_vel`` once robot2 is spawned), so that it follows whichever
  model the grader judges the robot.

Sending never holds the world: lines go through a bounded queue to a thread;
when the grader is slow, frames are dropped first, then states, and the
number dropped is sent when the queue has room again.
"""
import base64
import json
import math
import os
import queue
import socket
import threading

import cv2

from exp_assignment2.sim.model_facts import describe

SOCKET_ENV = 'EXP2_GRADER_SOCKET'
TOPICS_ENV = 'EXP2_GRADER_TOPICS'       # comma-separated topic names to relay
FRAME_WIDTH = 320                        # px: a frame's width in the record
QUEUE_SIZE = 4000


class GroundTruthLink(object):
    """A connection to the grader's socket; :meth:`send` queues a line."""

    def __init__(self, path, connect_timeout=5.0):
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self.sock.settimeout(connect_timeout)
        self.sock.connect(path)            # OSError: the caller says why, once
        self.sock.settimeout(None)
        self._queue = queue.Queue(QUEUE_SIZE)
        self.dropped = 0
        self.closed = False
        self._thread = threading.Thread(target=self._send_loop, name='ground-truth',
                                        daemon=True)
        self._thread.start()

    def send(self, record, droppable=False):
        if self.closed:
            return
        if droppable and self._queue.qsize() > QUEUE_SIZE // 2:
            self.dropped += 1
            return
        try:
            self._queue.put_nowait(record)
        except queue.Full:
            self.dropped += 1

    def _send_loop(self):
        while True:
            record = self._queue.get()
            if record is None:
                break
            if self.dropped:
                record = dict(record, dropped_before=self.dropped)
                self.dropped = 0
            try:
                self.sock.sendall((json.dumps(record, separators=(',', ':')) + '\n').encode())
            except OSError:
                self.closed = True
                break

    def close(self, timeout=2.0):
        if not self.closed:
            self._queue.put(None)
            self._thread.join(timeout)
        self.closed = True
        self.sock.close()


def _finite(value):
    return round(value, 4) if math.isfinite(value) else None


class GroundTruth(object):
    """Samples an :class:`~exp_assignment2.sim.engine.Engine` every ``period``
    s of simulated time into a :class:`GroundTruthLink` (a step listener)."""

    def __init__(self, engine, link, period=0.1, frame_period=1.0):
        self.engine, self.link = engine, link
        self.period, self.frame_period = float(period), float(frame_period)
        self._next = 0.0
        self._next_frame = {}
        self._described, self._generation = {}, None     # name -> the Model described
        self.model_listeners = []        # fn(model) for each model described (the host's)
        ball = engine.scripted_ball
        link.send({'kind': 'hello', 'pid': os.getpid(), 'time': engine.time,
                   'models': list(engine.models), 'ros_release': engine.release.name,
                   'ball_script': ball.setting.to_dict() if ball is not None else None})
        self._describe_changes()

    def _describe_changes(self):
        """A 'model' record for each model spawned since the last call (a name
        spawned again is a new model), a 'deleted' one for each one gone."""
        if self._generation == self.engine.generation:
            return
        self._generation = self.engine.generation
        now = round(self.engine.time, 4)
        for name in [n for n in self._described if n not in self.engine.models]:
            del self._described[name]
            self.link.send({'kind': 'deleted', 't': now, 'name': name})
        for name, model in list(self.engine.models.items()):
            if self._described.get(name) is not model:
                self._described[name] = model
                self.link.send({'kind': 'model', 't': now, 'facts': describe(
                    model, self.engine.plugins.get(name, ()), self.engine.release.name)})
                for listener in self.model_listeners:
                    listener(model)

    def __call__(self, engine):
        self._describe_changes()
        now = engine.time
        if now < self._next - 2 * self.period:      # the clock went back (reset_simulation)
            self._next = now
        if now + 1e-9 < self._next:
            return
        self._next = now + self.period
        self.link.send(self.sample(now), droppable=True)

    def sample(self, now):
        models, joints, fed, placed, ignored = {}, {}, {}, {}, {}
        for name, model in list(self.engine.models.items()):
            taken = sum(plugin.commands_taken for plugin in self.engine.plugins.get(name, ()))
            if model.script is not None:        # a ball script moves it: nothing else did
                taken, ignored[name] = 0, taken + model.ignored
            if taken:
                fed[name] = taken
            if model.placed:
                placed[name] = model.placed
            (x, y, z), quat = model.pose()
            siny = 2.0 * (quat[3] * quat[2] + quat[0] * quat[1])
            cosy = 1.0 - 2.0 * (quat[1] * quat[1] + quat[2] * quat[2])
            models[name] = [_finite(x), _finite(y), _finite(z), _finite(math.atan2(siny, cosy))]
            if model.movable_joints:
                names, positions, _, _ = model.joint_states()
                joints[name] = {n: _finite(v) for n, v in zip(names, positions)}
        record = {'kind': 'state', 't': round(now, 4), 'models': models, 'joints': joints}
        if fed:
            record['fed'] = fed
        if placed:
            record['placed'] = placed
        if any(ignored.values()):
            record['ignored'] = {name: n for name, n in ignored.items() if n}
        return record

    def offer_frame(self, camera, when, bgr):
        """A camera's finished frame (its worker thread): kept at most once per
        ``frame_period`` s of simulated time, made small."""
        if when + 1e-9 < self._next_frame.get(camera, 0.0):
            return
        self._next_frame[camera] = when + self.frame_period
        height, width = bgr.shape[:2]
        if width > FRAME_WIDTH:
            bgr = cv2.resize(bgr, (FRAME_WIDTH, max(1, height * FRAME_WIDTH // width)),
                             interpolation=cv2.INTER_AREA)
        ok, data = cv2.imencode('.jpg', bgr, [cv2.IMWRITE_JPEG_QUALITY, 70])
        if ok:
            self.link.send({'kind': 'frame', 't': round(when, 4), 'camera': camera,
                            'jpeg': base64.b64encode(data.tobytes()).decode()},
                           droppable=True)

    def topic(self, now, topic, message):
        self.link.send({'kind': 'topic', 't': round(now, 4), 'topic': topic, 'msg': message})

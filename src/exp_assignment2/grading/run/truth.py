"""The grader's end of the ground truth (no ROS): a Unix socket outside the
sandbox, where the simulator streams what happens
(:mod:`exp_assignment2.sim.ground_truth`).

Only the first connection from a simulator process is taken: the peer's
process (its credentials, seen from outside the sandbox's namespaces) must
run this package's simulator, from the source tree or through catkin's
relay or installed copy, from a file the run cannot write
(:mod:`exp_assignment2.grading.run.peer`), or the connection is refused and
counted.
What arrives is written as it arrives to the run's record, outside every
directory the sandbox can write: states and topics to ``truth.jsonl``,
frames to ``frames/`` as JPEG files, and twice a wall second a pair of
(simulated s, wall s) to ``clock.jsonl``: what maps the run's other wall
times (its windows' pictures) to simulated time.
"""
import base64
import collections
import json
import os
import socket
import threading
import time

from exp_assignment2.grading.run.peer import peer_process, runs_our_simulator

MAX_LINE = 8 * 1024 * 1024
CLOCK_EVERY = 0.5       # wall s between two (simulated, wall) pairs in clock.jsonl


class TruthServer(object):
    """Listens on ``path``; records into ``record_dir``. ``latest`` is the
    last simulated time heard and the monotonic wall time it came at."""

    def __init__(self, path, record_dir, may_write=None, accept=None):
        self.path, self.record_dir = path, record_dir
        self.accept_peer = accept or (lambda argv, executable: runs_our_simulator(
            argv, may_write=may_write, executable=executable))
        os.makedirs(os.path.join(record_dir, 'frames'), exist_ok=True)
        if os.path.exists(path):
            os.unlink(path)
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self.sock.bind(path)
        os.chmod(path, 0o777)       # the sandbox's user is not the grader's
        self.sock.listen(8)
        self.sock.settimeout(0.5)
        self.connected = threading.Event()
        self.simulator = None        # (pid, command line) of the accepted peer
        self.refused = []            # command lines of the refused peers
        self.first = self.latest = None        # (sim t, monotonic wall)
        self.states = self.frames = self.topics = self.dropped = 0
        self.closed = threading.Event()
        self._lock = threading.Lock()          # the reader writes, close() closes
        self._reader = None
        self._out = open(os.path.join(record_dir, 'truth.jsonl'), 'w')
        self._clock = open(os.path.join(record_dir, 'clock.jsonl'), 'w')
        self._clock_last = None
        self._thread = threading.Thread(target=self._serve, name='truth', daemon=True)
        self._thread.start()

    def _serve(self):
        while not self.closed.is_set():
            try:
                conn, _ = self.sock.accept()
            except socket.timeout:
                continue
            except OSError:
                break
            pid, argv, executable = peer_process(conn)
            if self.simulator is not None or not self.accept_peer(argv, executable):
                self.refused.append(' '.join(argv) or 'pid %d' % pid)
                conn.close()
                continue
            self.simulator = (pid, ' '.join(argv))
            self.connected.set()
            self._reader = threading.Thread(target=self._read, args=(conn,),
                                            name='truth-read', daemon=True)
            self._reader.start()

    def _read(self, conn):
        conn.settimeout(0.5)
        buffer = b''
        with conn:
            while not self.closed.is_set():
                try:
                    chunk = conn.recv(1 << 16)
                except socket.timeout:
                    continue
                except OSError:
                    break
                if not chunk:
                    break
                buffer += chunk
                while b'\n' in buffer:
                    line, buffer = buffer.split(b'\n', 1)
                    self._record(line)
                if len(buffer) > MAX_LINE:
                    buffer = b''

    def _record(self, line):
        try:
            record = json.loads(line)
        except ValueError:
            return
        if not isinstance(record, dict):
            return
        self.dropped += int(record.get('dropped_before') or 0)
        kind = record.get('kind')
        t = record.get('t')
        if isinstance(t, (int, float)):
            now = (float(t), time.monotonic())
            self.latest = now
            self._note_clock(float(t))
            if self.first is None:
                self.first = now
        if kind == 'frame':
            try:
                data = base64.b64decode(record.get('jpeg', ''))
            except ValueError:
                return
            camera = str(record.get('camera', 'camera')).replace('/', '_')
            name = '%s_%08.2f.jpg' % (camera, float(t or 0))
            with open(os.path.join(self.record_dir, 'frames', name), 'wb') as f:
                f.write(data)
            self.frames += 1
            return
        if kind == 'state':
            self.states += 1
        elif kind == 'topic':
            self.topics += 1
        with self._lock:
            if not self._out.closed:
                self._out.write(line.decode(errors='replace') + '\n')

    def _note_clock(self, t):
        wall = time.time()      # the clock the sandbox's processes read too
        if self._clock_last is not None and wall - self._clock_last < CLOCK_EVERY:
            return
        self._clock_last = wall
        with self._lock:
            if not self._clock.closed:
                self._clock.write('[%.3f, %.3f]\n' % (t, wall))

    def real_time_factor(self):
        if self.first is None or self.latest is None or self.latest[1] <= self.first[1]:
            return None
        return (self.latest[0] - self.first[0]) / (self.latest[1] - self.first[1])

    def close(self):
        self.closed.set()
        self._thread.join(2.0)
        if self._reader is not None:      # it notices within its 0.5 s timeout
            self._reader.join(2.0)
        self.sock.close()
        with self._lock:
            self._out.close()
            self._clock.close()
        try:
            os.unlink(self.path)
        except OSError:
            pass


TruthRecord = collections.namedtuple('TruthRecord', 'states topics hello models')


def read_record(record_dir):
    """The :class:`TruthRecord` of a run's truth.jsonl: its states, topics, hello,
    and what the simulator said of each model (name -> its last facts)."""
    states, topics, hello, models = [], [], None, {}
    path = os.path.join(record_dir, 'truth.jsonl')
    if not os.path.exists(path):
        return TruthRecord(states, topics, hello, models)
    with open(path, errors='replace') as f:
        for line in f:
            try:
                record = json.loads(line)
            except ValueError:
                continue
            kind = record.get('kind')
            if kind == 'state' and isinstance(record.get('models'), dict):
                record.setdefault('joints', {})
                states.append(record)
            elif kind == 'topic':
                topics.append((record.get('t', 0.0), record.get('topic'), record.get('msg')))
            elif kind == 'hello':
                hello = record
            elif kind == 'model' and isinstance(record.get('facts'), dict) and \
                    isinstance(record['facts'].get('name'), str):
                models[record['facts']['name']] = record['facts']
    return TruthRecord(states, topics, hello, models)


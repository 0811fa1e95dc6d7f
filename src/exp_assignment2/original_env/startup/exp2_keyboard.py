"""The keyboard of a process whose standard input is not a terminal (installed by sitecustomize.py).

Nodes of the original course asked a person: ``raw_input("Command: (m)ove
ball, (d)isappear ball: ")`` in a node that roslaunch started with
``output="screen"``, or that was started by rosrun in a terminal, waited for
someone to type. Started with standard input at /dev/null (the grader does,
and so does any service), the same call gets end-of-file at once and the node
dies of an EOFError. Here such a node waits as on a terminal nobody types into:

* ``input()``, ``sys.stdin.readline()``, ``.read()``, ``.readlines()`` and
  ``for line in sys.stdin``, called from the program's own code (not from
  the interpreter's libraries or an installed package), block the calling
  thread for good when standard input gives end-of-file before any data
  (/dev/null, an empty file or pipe, a closed descriptor). Other threads
  (rospy's callbacks and timers) go on; Ctrl-C (SIGINT, a KeyboardInterrupt
  in the main thread) and signals end the process as on a terminal, and so
  does rospy's shutdown (which swallows Ctrl-C's KeyboardInterrupt) in a
  node that initialised rospy: the wait ends with a KeyboardInterrupt. One
  line says where, once:
  ``[original-env] waited for keyboard input at scripts/command_request.py:37``
  (the file relative to its ROS package, and the line of the call);
* unless lines to type are given in ``EXP2_KEYBOARD`` (below): each is
  returned at its time, echoed after the prompt as a terminal echoes what is
  typed, then the reading waits as above.

Standard input that has data is read as it is, to its end. A terminal is
never touched. EXP2_KEYBOARD_WAIT=0 turns all this off.

``EXP2_KEYBOARD``: JSON, or the path of a file holding it: a list of
``{"at": SECONDS, "text": "m"}``, or an object whose keys name the process
that gets the list: its node name (``__name:=``), its script's file name,
or ``"*"`` for any other. SECONDS are ROS time (``/clock``) once the node has
initialised rospy with simulated time, else seconds since the process started.
"""
import builtins
import json
import os
import sys
import threading
import time

import exp2_py2_read

ENV = 'EXP2_KEYBOARD'
NOTICE = '[original-env] waited for keyboard input at %s\n'
_HERE = __file__  # as in its code objects


class KeyboardError(ValueError):
    """EXP2_KEYBOARD cannot be read: the one line to print."""


def _process_keys(argv):
    keys = [a.split(':=', 1)[1] for a in argv[1:] if a.startswith('__name:=')]
    if argv and argv[0]:
        keys.append(os.path.basename(argv[0]))
    return keys + ['*']


def _lines_of_this_process():
    try:
        return lines_to_type(os.environ.get(ENV, ''), getattr(sys, 'argv', None) or [''])
    except KeyboardError as exc:
        sys.stderr.write('[original-env] %s: %s; nothing is typed\n' % (ENV, exc))
        return []


def lines_to_type(value, argv):
    """[(at, text)] of EXP2_KEYBOARD's ``value`` for the process of ``argv``, in time order."""
    if not value.strip():
        return []
    if value.lstrip()[:1] not in '[{':
        try:
            with open(value) as f:
                value = f.read()
        except OSError as exc:
            raise KeyboardError('cannot read %s: %s' % (value, exc.strerror or exc))
    try:
        data = json.loads(value)
    except ValueError as exc:
        raise KeyboardError('not JSON: %s' % exc)
    shape = ('expected a list of {"at": SECONDS, "text": "..."}, or an object of such lists '
             'by node name, script name or "*"')
    if isinstance(data, dict):
        if not all(isinstance(v, list) for v in data.values()):
            raise KeyboardError(shape)
        data = next((data[k] for k in _process_keys(argv) if k in data), [])
    if not isinstance(data, list):
        raise KeyboardError(shape)
    found = []
    for item in data:
        at = item.get('at') if isinstance(item, dict) else None
        text = item.get('text') if isinstance(item, dict) else None
        if isinstance(at, bool) or not isinstance(at, (int, float)) or at < 0 or \
                not isinstance(text, str) or '\n' in text:
            raise KeyboardError('each line is {"at": SECONDS >= 0, "text": "one line"}, not %s'
                                % json.dumps(item))
        found.append((float(at), text))
    return sorted(found, key=lambda line: line[0])


def shown(path):
    """``path`` relative to its ROS package (the folder with package.xml), else to the
    current directory when below it, else as it is."""
    folder = os.path.dirname(os.path.abspath(path))
    while folder and folder != os.path.dirname(folder):
        if os.path.isfile(os.path.join(folder, 'package.xml')):
            return os.path.relpath(path, folder)
        folder = os.path.dirname(folder)
    relative = os.path.relpath(path)
    return path if relative.startswith(os.pardir) else relative


def program_frame(frame):
    """The frame that called this module, from ``frame`` out, if it is the program's own
    code (not the interpreter's libraries nor an installed package's); else None."""
    while frame is not None and frame.f_code.co_filename == _HERE:
        frame = frame.f_back
    if frame is None or exp2_py2_read.is_system_path(frame.f_code.co_filename):
        return None
    return frame


class KeyboardStdin(object):
    """``sys.stdin`` reading ``real`` to its end, then as a terminal's keyboard (see above)."""

    def __init__(self, real, lines=None):
        self._real = real
        self._lines = None if lines is None else list(lines)    # None: EXP2_KEYBOARD's, when due
        self._keyboard = real is None
        self._had_data = False
        self._typed = ''                # typed and not read yet
        self._lock = threading.RLock()
        self._stopped = threading.Event()       # rospy has shut down
        self._hooked = False
        self._told = False
        self._start = time.monotonic()
        self.prompt = ''

    def __getattr__(self, name):      # the rest is the real standard input's
        real = self.__dict__.get('_real')
        if real is None:
            raise AttributeError(name)
        return getattr(real, name)

    def isatty(self):
        return False

    def __iter__(self):
        return self

    def __next__(self):
        line = self.readline()
        if not line:
            raise StopIteration
        return line

    def readline(self, size=-1):
        size = -1 if size is None else size
        got = self._from_real('readline', size)
        if got is not None:
            return got
        with self._lock:
            while '\n' not in self._typed and not 0 <= size <= len(self._typed):
                self._type_next()
            end = self._typed.index('\n') + 1 if '\n' in self._typed else len(self._typed)
            end = end if size < 0 else min(end, size)
            line, self._typed = self._typed[:end], self._typed[end:]
            return line

    def read(self, size=-1):
        size = -1 if size is None else size
        got = self._from_real('read', size)
        if got is not None:
            return got
        with self._lock:
            while size < 0 or len(self._typed) < size:
                self._type_next()       # to the end of the input: never, on a terminal
            data, self._typed = self._typed[:size], self._typed[size:]
            return data

    def readlines(self, hint=-1):
        lines = []
        for line in self:
            lines.append(line)
            if 0 < hint <= sum(map(len, lines)):
                break
        return lines

    def _from_real(self, method, size):
        """What the real standard input gives, or None once it is the keyboard's turn."""
        if not self._keyboard:
            got = getattr(self._real, method)(size)
            if got or self._had_data:
                self._had_data = self._had_data or bool(got)
                return got
            if program_frame(sys._getframe(2)) is None:
                return got              # a library reading to the end: end-of-file
            self._keyboard = True
        return '' if program_frame(sys._getframe(2)) is None else None

    def _type_next(self):
        """Wait for the next line typed (held: the lock); past the last, forever."""
        if self._lines is None:     # sys.argv is the program's only now (not at start-up)
            self._lines = _lines_of_this_process()
        if not self._lines:
            self._tell(program_frame(sys._getframe(1)))
            self._lock.release()
            try:
                while not self._rospy_shut_down():
                    self._stopped.wait(1.0)     # the shutdown hook sets it; 1 s: a late init
            finally:
                self._lock.acquire()
            raise KeyboardInterrupt
        at, text = self._lines[0]
        self._wait_until(at)
        del self._lines[0]
        self._typed += text + '\n'
        try:        # a terminal echoes what is typed, after the prompt
            sys.stdout.write(text + '\n')
            sys.stdout.flush()
        except (AttributeError, OSError, ValueError):
            pass
        self.prompt = ''

    def _now(self):
        """(seconds, a condition notified when they change, or None)."""
        rospy = sys.modules.get('rospy')
        try:
            if rospy is not None and rospy.core.is_initialized() and \
                    not rospy.rostime.is_wallclock():
                return rospy.get_time(), rospy.rostime.get_rostime_cond()
        except Exception:       # rospy half imported or shut down: wall time
            pass
        return time.monotonic() - self._start, None

    def _rospy_shut_down(self):
        """Has rospy, initialised in this process, shut down? (Hears of it from now on.)"""
        rospy = sys.modules.get('rospy')
        try:
            core = rospy.core if rospy is not None else None
            if core is not None and not self._hooked and core.is_initialized():
                core.add_preshutdown_hook(lambda reason: self._stopped.set())
                self._hooked = True
            return self._hooked and (core.is_shutdown_requested() or core.is_shutdown())
        except Exception:       # rospy half imported: not initialised
            return False

    def _wait_until(self, at):
        while True:
            if self._rospy_shut_down():
                raise KeyboardInterrupt
            now, changed = self._now()
            if now >= at:
                return
            if changed is None:
                self._stopped.wait(min(at - now, 0.5))
            else:
                with changed:
                    changed.wait(0.5)

    def _tell(self, frame):
        if self._told:
            return
        self._told = True
        where = '%s:%d' % (shown(frame.f_code.co_filename), frame.f_lineno) if frame \
            else 'an unknown place'
        try:
            sys.stdout.flush()
            lead = '\n' if self.prompt and not self.prompt.endswith('\n') and \
                _same_file(sys.stdout, sys.stderr) else ''
            sys.stderr.write(lead + NOTICE % where)
            sys.stderr.flush()
        except (AttributeError, OSError, ValueError):
            pass


def _same_file(a, b):
    try:
        first, second = os.fstat(a.fileno()), os.fstat(b.fileno())
    except (AttributeError, OSError, ValueError):
        return False
    return (first.st_dev, first.st_ino) == (second.st_dev, second.st_ino)


def install():
    """Put :class:`KeyboardStdin` in ``sys.stdin`` when standard input is not a
    terminal (idempotent), and have ``input`` tell it the prompt."""
    if os.isatty(0) or isinstance(sys.stdin, KeyboardStdin):
        return
    import exp2_hidden_frames
    exp2_hidden_frames.hide(_HERE, and_below=True)  # a Ctrl-C ends on the student's line
    stdin = sys.stdin = KeyboardStdin(sys.stdin)
    real_input = builtins.input

    def keyboard_input(*prompt):
        stdin.prompt = str(prompt[0]) if prompt else ''
        return real_input(*prompt)
    keyboard_input.__doc__ = real_input.__doc__
    builtins.input = keyboard_input

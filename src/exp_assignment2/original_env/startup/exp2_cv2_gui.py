"""Run every OpenCV HighGUI call of the process on one dedicated thread.

Why: Debian's python3-opencv draws windows with Qt5. OpenCV's Qt backend
creates the QApplication in the first thread that shows a window; a call from
any other thread is queued to that thread with a *blocking* connection and
switches the backend to "multi-thread" mode, in which ``waitKey`` only waits
on a condition variable and no longer processes Qt events. Nobody processes
the queued call, so the second thread's ``cv2.imshow`` never returns (and the
first thread's window stops repainting). The original assignment calls
``cv2.imshow(...); cv2.waitKey(2)`` from every camera subscriber callback,
and rospy runs each subscription's callbacks in its own thread.

What this does: after ``cv2`` is imported, the HighGUI functions are replaced
by wrappers that hand the work to a single daemon thread ("cv2-highgui"),
which owns the QApplication and all windows and pumps Qt events
(``waitKeyEx`` with a short tick) after each frame it draws and every
``EVENTS_PERIOD`` while a window exists. So OpenCV only ever
sees one GUI thread, its single-thread mode, which works.

* ``imshow`` from another thread copies the frame, keeps only the newest
  frame per window and returns at once; the GUI thread draws it a few ms
  later. Invalid arguments still raise in the caller (None and empty arrays
  are checked by OpenCV before any GUI work; other odd types are shown
  synchronously so their error is re-raised in the caller). An error while
  drawing a handed-over frame is printed once per window on stderr.
* ``waitKey``/``waitKeyEx``/``pollKey`` return a key typed in any window (or
  -1), waiting at most their delay; ``waitKey(0)`` waits for a key until no
  window is left. Without any window they return -1 at once, as OpenCV does.
* Every other window function runs synchronously on the GUI thread (results
  and exceptions come back to the caller); mouse and trackbar callbacks run on
  the GUI thread.
* Calls made on the GUI thread itself (e.g. from a mouse callback) go straight
  to OpenCV.
* At exit the thread closes the windows and stops; being a daemon thread it
  never keeps the process alive.

Installed through exp2_cv2_import.py by sitecustomize.py (same directory), i.e. only inside
tools/original_env/shell.sh, and only when a display is configured.
"""
import atexit
import collections
import sys
import threading
import time

# HighGUI functions that must run on the GUI thread (those cv2 has are wrapped).
SYNC_FUNCTIONS = (
    'namedWindow', 'destroyWindow', 'destroyAllWindows', 'moveWindow',
    'resizeWindow', 'setWindowTitle', 'setWindowProperty', 'getWindowProperty',
    'getWindowImageRect', 'createTrackbar', 'getTrackbarPos', 'setTrackbarPos',
    'setTrackbarMin', 'setTrackbarMax', 'setMouseCallback', 'displayOverlay',
    'displayStatusBar', 'addText', 'createButton', 'startWindowThread',
    'selectROI', 'selectROIs', 'setOpenGlContext', 'setOpenGlDrawCallback',
    'updateWindow',
)
TICK_MS = 1            # how long each event-pumping waitKey of the GUI thread lasts
# s between two pumps while no frame comes: pumping back to back (waitKey(5) in
# a loop) cost a process with one window 0.048 of a core, once every 50 ms 0.008
EVENTS_PERIOD = 0.05
VISIBILITY_PERIOD = 0.2  # s between checks for windows closed by the user
MARKER = '_exp2_gui_thread'


class _Call(object):
    """A synchronous call waiting for the GUI thread."""

    def __init__(self, fn, args, kwargs):
        self.fn, self.args, self.kwargs = fn, args, kwargs
        self.done = threading.Event()
        self.result = self.error = None


class GuiThread(object):
    def __init__(self, cv2):
        self.cv2 = cv2
        self.real = {}
        for name in ('imshow', 'waitKey', 'waitKeyEx', 'pollKey') + SYNC_FUNCTIONS:
            if hasattr(cv2, name):
                self.real[name] = getattr(cv2, name)
        self.cond = threading.Condition()
        self.queue = collections.deque()  # ('show', name, box) or _Call, in call order
        self.pending = {}                 # window -> box [frame] of its queued 'show'
        self.keys = collections.deque(maxlen=64)
        self.windows = set()  # windows shown and not closed (all guarded by cond)
        self.inflight = 0     # queue items the GUI thread has taken but not finished
        self.thread = None
        self.stopping = False
        self.legacy_keys = False
        self.reported = set()

    # -- caller side ------------------------------------------------------
    def on_gui_thread(self):
        return threading.current_thread() is self.thread

    def _start(self):
        # with self.cond held
        if self.thread is None:
            self.thread = threading.Thread(target=self._run, name='cv2-highgui', daemon=True)
            self.thread.start()
            atexit.register(self.stop)

    def imshow(self, winname, mat):
        if self.on_gui_thread():
            return self.real['imshow'](winname, mat)
        np = sys.modules.get('numpy')
        is_array = np is not None and isinstance(mat, np.ndarray)
        if mat is None or (is_array and mat.size == 0) or not isinstance(winname, str):
            # OpenCV rejects these before touching the GUI: same error, same thread.
            return self.real['imshow'](winname, mat)
        if not is_array:
            return self.call(self.real['imshow'], winname, mat)
        frame = mat.copy()  # the caller may reuse its buffer once we return
        with self.cond:
            if self.stopping:
                return None
            self._start()
            box = self.pending.get(winname)
            if box is None:
                box = self.pending[winname] = [frame]
                self.queue.append(('show', winname, box))
            else:
                box[0] = frame  # not drawn yet: only the newest frame matters
            self.cond.notify_all()
        return None

    def call(self, fn, *args, **kwargs):
        if self.on_gui_thread():
            return fn(*args, **kwargs)
        job = _Call(fn, args, kwargs)
        with self.cond:
            if self.stopping:
                return None
            self._start()
            self.pending = {}  # later imshows must be drawn after this call
            self.queue.append(job)
            self.cond.notify_all()
        job.done.wait()
        if job.error is not None:
            raise job.error
        return job.result

    def wait_key_ex(self, delay=0):
        if self.on_gui_thread():
            return self.real.get('waitKeyEx', self.real['waitKey'])(delay)
        deadline = None if delay <= 0 else time.monotonic() + delay / 1000.0
        with self.cond:
            if self.thread is None:
                return -1  # no window was ever created: OpenCV returns at once
            while not self.keys:
                idle = not (self.windows or self.queue or self.inflight)
                if self.stopping or (deadline is None and idle):
                    return -1  # waitKey(0) with no window left, as OpenCV
                timeout = 0.1 if deadline is None else deadline - time.monotonic()
                if timeout <= 0:
                    return -1
                self.cond.wait(timeout)
            return self.keys.popleft()

    def wait_key(self, delay=0):
        code = self.wait_key_ex(delay)
        if self.legacy_keys:
            return code
        return -1 if code == -1 else code & 0xFF  # as cv::waitKey does

    def poll_key(self):
        if self.on_gui_thread():
            return self.real['pollKey']()  # only wrapped when cv2 has it
        with self.cond:
            return self.keys.popleft() if self.keys else -1

    def stop(self):
        with self.cond:
            self.stopping = True
            self.cond.notify_all()
        if self.thread is not None and not self.on_gui_thread():
            self.thread.join(2.0)

    # -- GUI thread -------------------------------------------------------
    def _run(self):
        next_check = 0.0
        try:
            while True:
                with self.cond:
                    while not (self.queue or self.windows or self.stopping):
                        self.cond.wait()
                    if not (self.queue or self.stopping):
                        # windows, nothing to draw: their events now and then; a frame
                        # or a call wakes the thread at once
                        self.cond.wait(EVENTS_PERIOD)
                    if self.stopping and not self.queue:
                        break
                    items = list(self.queue)
                    self.queue.clear()
                    self.inflight = len(items)
                for item in items:
                    self._do(item)
                with self.cond:
                    self.inflight = 0
                    any_window = bool(self.windows)
                    self.cond.notify_all()
                if any_window:
                    self._pump()
                    if time.monotonic() >= next_check:
                        next_check = time.monotonic() + VISIBILITY_PERIOD
                        self._forget_closed_windows()
        finally:
            try:
                self.real['destroyAllWindows']()
                self.real['waitKey'](1)
            except Exception:
                pass
            with self.cond:
                self.windows.clear()
                self.stopping = True
                self.cond.notify_all()

    def _do(self, item):
        if isinstance(item, _Call):
            try:
                item.result = item.fn(*item.args, **item.kwargs)
                self._track(item.fn, item.args)
            except BaseException as exc:  # handed back to the caller
                item.error = exc
            item.done.set()
            return
        _, name, box = item
        with self.cond:
            if self.pending.get(name) is box:
                del self.pending[name]
            frame = box[0]
        try:
            self.real['imshow'](name, frame)
            self._track(self.real['imshow'], (name,))
        except Exception as exc:
            key = (name, str(exc))
            if key not in self.reported:
                self.reported.add(key)
                sys.stderr.write('[cv2 GUI thread] cv2.imshow(%r, ...) failed: %s\n' % (name, exc))

    def _track(self, fn, args):
        """Keep the set of open windows (waitKey(0) returns when it is empty)."""
        real = self.real
        with self.cond:
            if fn is real.get('imshow') or fn is real.get('namedWindow'):
                self.windows.add(args[0])
            elif fn is real.get('destroyWindow'):
                self.windows.discard(args[0])
            elif fn is real.get('destroyAllWindows'):
                self.windows.clear()
            self.cond.notify_all()

    def _pump(self):
        wait = self.real.get('waitKeyEx', self.real['waitKey'])
        code = wait(TICK_MS)
        if code != -1:
            with self.cond:
                self.keys.append(code)
                self.cond.notify_all()

    def _forget_closed_windows(self):
        get = self.real.get('getWindowProperty')
        if get is None:
            return
        with self.cond:
            names = list(self.windows)
        closed = set()
        for name in names:
            try:
                if get(name, self.cv2.WND_PROP_VISIBLE) < 1:
                    closed.add(name)
            except Exception:
                closed.add(name)
        if closed:
            with self.cond:
                self.windows -= closed
                self.cond.notify_all()

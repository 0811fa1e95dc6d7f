"""The cameras' frame worker: one thread that finishes every camera's frames
(renders with ``gl``, converts, encodes, publishes) and owns the renderer's
GL context. The hand-over holds one frame, so a simulator that is ahead
waits instead of dropping or queueing frames."""
import queue
import threading
import time

import cv2

FRAME_ERRORS = (cv2.error, ValueError, RuntimeError, OSError)   # a bad frame, not a dead camera


class FrameWorker(object):
    """Finishes frames for the cameras of one engine.

    :param kind: renderer name (gl, egl, tiny); a ``gl`` that cannot start
        falls back to ``tiny`` with one warning
    :param engine: the plugins' :class:`~.base.EngineHandle`
    """

    def __init__(self, kind, engine):
        self.log = engine.log
        self.backend = engine.make_renderer(kind)
        self.jobs = queue.Queue(maxsize=1)
        self.started = threading.Event()
        self.error, self._last_error = None, -1e9
        self.thread = threading.Thread(target=self._run, name='camera', daemon=True)
        self.thread.start()
        self.started.wait()
        if self.error is not None:
            self.log.warn('camera: renderer %s cannot start (%s); using tiny instead'
                          % (kind, self.error))
            self.backend = engine.make_renderer('tiny')
            self.thread = threading.Thread(target=self._loop, name='camera', daemon=True)
            self.thread.start()
        self.log.info('camera: renderer %s' % self.backend.name)

    def _run(self):
        try:
            self.backend.start()        # a GL context belongs to this thread
        except RuntimeError as exc:
            self.error = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
            self.started.set()
            return
        self.started.set()
        self._loop()

    def _loop(self):
        while True:
            item = self.jobs.get()
            try:
                if item is None:
                    break
                camera, when, job = item
                camera.publish(when, self.backend.finish(job))
            except FRAME_ERRORS as exc:     # a bad frame must not stop the camera
                if time.monotonic() - self._last_error > 10.0:
                    self._last_error = time.monotonic()
                    self.log.error('camera: frame dropped: %s' % exc)
            finally:
                self.jobs.task_done()
        self.backend.close()

    def submit(self, camera, when, job):
        """Hand a captured frame over; waits while the worker is busy."""
        self.jobs.put((camera, when, job))

    def drain(self):
        """Wait until every frame handed over is published (a camera closes)."""
        if self.thread.is_alive():
            self.jobs.join()

    def close(self):
        if self.thread.is_alive():
            self.jobs.put(None)
            self.thread.join(5.0)

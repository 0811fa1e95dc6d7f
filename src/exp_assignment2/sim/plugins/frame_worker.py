"""The cameras' frame workers: two threads that finish every camera's frames.
The first draws (with ``gl`` it owns the renderer's GL context), the second
encodes and publishes, so that a frame is drawn while the one before it is
encoded: both wait outside Python's GIL (Mesa's rasteriser, libjpeg). Each
hand-over holds one frame, so a simulator that is ahead waits instead of
dropping or queueing frames. A frame whose scene did not change (the
backend's ``Still`` job) goes through both in its turn, undrawn: the camera
publishes its last frame's bytes again (``publish(when, image, same)``)."""
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
        self.jobs = queue.Queue(maxsize=1)       # captured, to draw
        self.drawn = queue.Queue(maxsize=1)      # drawn, to encode and publish
        self.started = threading.Event()
        self.error, self._last_error = None, -1e9
        self.publisher = threading.Thread(target=self._publish_loop, name='camera publish',
                                          daemon=True)
        self.publisher.start()
        self.thread = threading.Thread(target=self._run, name='camera', daemon=True)
        self.thread.start()
        self.started.wait()
        if self.error is not None:
            self.log.warn('camera: renderer %s cannot start (%s); using tiny instead'
                          % (kind, self.error))
            self.backend = engine.make_renderer('tiny')
            self.thread = threading.Thread(target=self._draw_loop, name='camera', daemon=True)
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
        self._draw_loop()

    def _draw_loop(self):
        while True:
            item = self.jobs.get()
            try:
                if item is None:
                    self.drawn.put(None)
                    break
                camera, when, job = item
                self.drawn.put((camera, when, self.backend.finish(job),
                                getattr(job, 'same', False)))
            except FRAME_ERRORS as exc:     # a bad frame must not stop the camera
                self._forget(item)
                self._dropped(exc)
            finally:
                self.jobs.task_done()
        self.backend.close()

    def _publish_loop(self):
        while True:
            item = self.drawn.get()
            try:
                if item is None:
                    break
                camera, when, image, same = item
                camera.publish(when, image, same)
            except Exception as exc:
                # whatever the camera's transport raises (rospy: a topic closed
                # by the shutdown under way): were this thread to end, the
                # drawing thread would wait on its hand-over for good, and
                # close() 5 s for it
                self._dropped(exc)
            finally:
                self.drawn.task_done()

    def _forget(self, item):
        """A frame not drawn: the camera's next one is drawn, whatever it shows."""
        forget = getattr(self.backend, 'forget', None)
        if forget is not None and item:
            forget(getattr(item[0], 'spec', item[0]))

    def _dropped(self, exc):
        if time.monotonic() - self._last_error > 10.0:
            self._last_error = time.monotonic()
            self.log.error('camera: frame dropped: %s' % exc)

    def submit(self, camera, when, job):
        """Hand a captured frame over; waits while the worker is busy."""
        self.jobs.put((camera, when, job))

    def drain(self):
        """Wait until every frame handed over is published (a camera closes)."""
        if self.thread.is_alive():
            self.jobs.join()
        if self.publisher.is_alive():
            self.drawn.join()

    def close(self):
        if self.thread.is_alive():
            self.jobs.put(None)          # passed on to the publishing thread
            self.thread.join(5.0)
        elif self.publisher.is_alive():
            self.drawn.put(None)
        self.publisher.join(5.0)


def shared_worker(engine):
    """The engine's one :class:`FrameWorker` (a plugin's
    :class:`~.base.EngineHandle`), made by the first camera that asks."""
    return engine.shared('camera.worker', lambda: FrameWorker(
        engine.settings.get('renderer', 'gl'), engine))

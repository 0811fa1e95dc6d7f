"""A headless OpenGL 3.3 context (moderngl over EGL) for the GL renderer.

:class:`GLContext` creates the context in, and binds it to, the constructing
thread, and makes it current only inside :meth:`GLContext.current`, restoring
whatever EGL context and surfaces the thread had before: pybullet's EGL
plugin may share the thread and must neither draw into ours nor we into its.
"""
import contextlib
import ctypes
import threading

EGL_DRAW, EGL_READ = 0x3059, 0x305A


def _gl_finish():
    """glFinish of libglvnd's dispatch (to the thread's current context), or None."""
    for library in ('libOpenGL.so.0', 'libGL.so.1'):
        try:
            return ctypes.CDLL(library).glFinish    # ctypes releases the GIL in the call
        except (OSError, AttributeError):
            pass
    return None


_GL_FINISH = _gl_finish()


def one_line(exc):
    """An exception's message on one line (its type name if it has none)."""
    return ' '.join(str(exc).split()) or type(exc).__name__


class _EglCurrent(object):
    """Saves and restores this thread's current EGL context *with* its surfaces:
    moderngl's ``with ctx`` restores the previous context without them, which
    crashes pybullet's EGL plugin if it runs in the same thread (seen)."""

    def __init__(self):
        egl = self.egl = ctypes.CDLL('libEGL.so.1')
        for name in ('eglGetCurrentDisplay', 'eglGetCurrentSurface', 'eglGetCurrentContext'):
            getattr(egl, name).restype = ctypes.c_void_p
        egl.eglGetCurrentSurface.argtypes = [ctypes.c_int]
        egl.eglMakeCurrent.argtypes = [ctypes.c_void_p] * 4

    def save(self):
        e = self.egl
        return (e.eglGetCurrentDisplay(), e.eglGetCurrentSurface(EGL_DRAW),
                e.eglGetCurrentSurface(EGL_READ), e.eglGetCurrentContext())

    def restore(self, saved):
        if saved[0] and saved[3]:   # nothing was current before: leave ours
            self.egl.eglMakeCurrent(*saved)


class GLContext(object):
    """A standalone moderngl context bound to the thread that constructs it.

    Raises RuntimeError with a one-line message starting 'gl renderer
    unavailable' when moderngl cannot be imported or no EGL OpenGL 3.3
    context can be created. ``ctx`` is the moderngl context (None once
    released); use it only inside ``with self.current():``.
    """

    def __init__(self):
        try:
            import moderngl
        except ImportError as exc:
            raise RuntimeError('gl renderer unavailable: cannot import moderngl (%s)'
                               % one_line(exc))
        try:
            self._egl = _EglCurrent()
            saved = self._egl.save()
            self.ctx = moderngl.create_standalone_context(backend='egl', require=330)
            self._egl.restore(saved)   # creating it made it current
        except Exception as exc:
            raise RuntimeError('gl renderer unavailable: no EGL OpenGL 3.3 context (%s)'
                               % one_line(exc))
        self.thread = threading.get_ident()

    def check_thread(self, what):
        """RuntimeError unless called from the thread that created the context."""
        if threading.get_ident() != self.thread:
            raise RuntimeError('%s called from a thread other than the one that '
                               'created its GL context' % what)

    @contextlib.contextmanager
    def current(self):
        """The context current for a block, the thread's previous one (with its
        surfaces) restored after."""
        saved = self._egl.save()
        self.ctx.__enter__()
        try:
            yield self.ctx
        finally:
            self._egl.restore(saved)

    def finish(self):
        """Wait for the drawing to be done without holding Python's GIL: Mesa
        rasterises when the image is read, and moderngl holds the GIL while it
        reads; through ctypes the simulator's other thread steps meanwhile."""
        if _GL_FINISH is not None:
            _GL_FINISH()

    def release(self):
        """Release the context itself (its objects first, by the caller)."""
        if self.ctx is not None:
            with self.current():
                self.ctx.release()
            self.ctx = None

"""Reading a window's pixels through the X server's MIT-SHM extension (no ROS).

python-xlib's ``GetImage`` makes the server write a window's pixels into the
socket and reads them back in pure Python: about 9 ms of the capture's CPU
for one 1500 x 850 window (an OpenCV window) and as much again in Xvfb,
every period, for every window. ``XShmGetImage`` has the server copy them
into a shared memory segment instead: 0.6 ms, the same bytes (measured on
Xvfb). The display's capture process (:mod:`.display`) reads through
:class:`ShmReader` and falls back to ``GetImage`` when it cannot be had
(no libXext, no MIT-SHM, no System V shared memory where it runs).

libX11's default error handler ends the process on any X error (a window
gone between listing and reading it, a common case): one that records the
error instead is installed, and a read that failed returns None.
"""
import ctypes
import threading

Z_PIXMAP = 2
ALL_PLANES = 0xffffffff
IPC_PRIVATE, IPC_CREAT, IPC_RMID = 0, 0o1000, 0
BITS_PER_PIXEL = 32         # Xvfb's 24-bit screen, as GetImage's ZPixmap reads it


def _row_bytes(width):
    return (width * BITS_PER_PIXEL + 31) // 32 * 4


class _Segment(ctypes.Structure):
    """XShmSegmentInfo."""
    _fields_ = [('shmseg', ctypes.c_ulong), ('shmid', ctypes.c_int),
                ('shmaddr', ctypes.c_void_p), ('readOnly', ctypes.c_int)]


class _Image(ctypes.Structure):
    """The head of Xlib's XImage (what is read here; the rest is Xlib's)."""
    _fields_ = [('width', ctypes.c_int), ('height', ctypes.c_int), ('xoffset', ctypes.c_int),
                ('format', ctypes.c_int), ('data', ctypes.c_void_p),
                ('byte_order', ctypes.c_int), ('bitmap_unit', ctypes.c_int),
                ('bitmap_bit_order', ctypes.c_int), ('bitmap_pad', ctypes.c_int),
                ('depth', ctypes.c_int), ('bytes_per_line', ctypes.c_int),
                ('bits_per_pixel', ctypes.c_int)]


_ERROR_HANDLER = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p)
_errors = threading.local()


@_ERROR_HANDLER
def _record_error(display, event):
    _errors.count = getattr(_errors, 'count', 0) + 1
    return 0


class ShmUnavailable(Exception):
    """MIT-SHM cannot be used here: read with GetImage instead."""


class ShmReader(object):
    """Window pixels (ZPixmap, 32 bits a pixel, as GetImage gives them)
    through one shared segment, made again when a larger one is needed."""

    def __init__(self, name):
        try:
            self.x11 = ctypes.CDLL('libX11.so.6')
            self.xext = ctypes.CDLL('libXext.so.6')
            self.libc = ctypes.CDLL(None, use_errno=True)
        except OSError as exc:
            raise ShmUnavailable(str(exc))
        self._declare()
        self.x11.XSetErrorHandler(_record_error)
        self.display = self.x11.XOpenDisplay(name.encode())
        if not self.display:
            raise ShmUnavailable('cannot open display %s' % name)
        self.segment, self.image, self.size = None, None, (0, 0)
        try:
            if not self.xext.XShmQueryExtension(self.display):
                raise ShmUnavailable('no MIT-SHM extension')
            self._make(64, 64)          # shared memory works here, or not
        except ShmUnavailable:
            self.close()
            raise

    def _declare(self):
        x11, xext, libc = self.x11, self.xext, self.libc
        x11.XOpenDisplay.restype, x11.XOpenDisplay.argtypes = ctypes.c_void_p, [ctypes.c_char_p]
        x11.XSetErrorHandler.argtypes = [_ERROR_HANDLER]
        x11.XSetErrorHandler.restype = ctypes.c_void_p
        for name in ('XDefaultVisual', 'XDefaultDepth'):
            getattr(x11, name).argtypes = [ctypes.c_void_p, ctypes.c_int]
        x11.XDefaultVisual.restype = ctypes.c_void_p
        x11.XSync.argtypes = [ctypes.c_void_p, ctypes.c_int]
        x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
        xext.XShmQueryExtension.argtypes = [ctypes.c_void_p]
        xext.XShmCreateImage.restype = ctypes.c_void_p
        xext.XShmCreateImage.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_uint,
                                         ctypes.c_int, ctypes.c_void_p,
                                         ctypes.POINTER(_Segment), ctypes.c_uint,
                                         ctypes.c_uint]
        for name in ('XShmAttach', 'XShmDetach'):
            getattr(xext, name).argtypes = [ctypes.c_void_p, ctypes.POINTER(_Segment)]
        xext.XShmGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_void_p,
                                      ctypes.c_int, ctypes.c_int, ctypes.c_ulong]
        libc.shmget.argtypes = [ctypes.c_int, ctypes.c_size_t, ctypes.c_int]
        libc.shmat.restype, libc.shmat.argtypes = ctypes.c_void_p, [
            ctypes.c_int, ctypes.c_void_p, ctypes.c_int]
        libc.shmdt.argtypes = [ctypes.c_void_p]
        libc.shmctl.argtypes = [ctypes.c_int, ctypes.c_int, ctypes.c_void_p]

    def _make(self, width, height):
        """A segment and an image of ``width`` x ``height`` attached to the server."""
        self._free()
        segment = _Segment()
        image = self.xext.XShmCreateImage(
            self.display, self.x11.XDefaultVisual(self.display, 0),
            self.x11.XDefaultDepth(self.display, 0), Z_PIXMAP, None, ctypes.byref(segment),
            width, height)
        if not image:
            raise ShmUnavailable('XShmCreateImage failed')
        head = ctypes.cast(image, ctypes.POINTER(_Image)).contents
        if head.bits_per_pixel != BITS_PER_PIXEL:
            self._destroy(image)
            raise ShmUnavailable('a screen of %d bits a pixel' % head.bits_per_pixel)
        segment.shmid = self.libc.shmget(IPC_PRIVATE, head.bytes_per_line * height,
                                         IPC_CREAT | 0o600)
        if segment.shmid < 0:
            self._destroy(image)
            raise ShmUnavailable('shmget: errno %d' % ctypes.get_errno())
        address = self.libc.shmat(segment.shmid, None, 0)
        if address in (None, ctypes.c_void_p(-1).value):
            self.libc.shmctl(segment.shmid, IPC_RMID, None)
            self._destroy(image)
            raise ShmUnavailable('shmat: errno %d' % ctypes.get_errno())
        segment.shmaddr, segment.readOnly, head.data = address, 0, address
        before = getattr(_errors, 'count', 0)
        self.xext.XShmAttach(self.display, ctypes.byref(segment))
        self.x11.XSync(self.display, 0)
        self.libc.shmctl(segment.shmid, IPC_RMID, None)   # gone once both detach
        self.segment, self.image, self.size = segment, image, (width, height)
        if getattr(_errors, 'count', 0) != before:      # the server could not attach it
            self._free()
            raise ShmUnavailable('the X server cannot attach shared memory here')

    def _destroy(self, image):
        head = ctypes.cast(image, ctypes.POINTER(_Image)).contents
        head.data = None            # the segment's, never Xlib's to free
        # XDestroyImage is a macro: the image's own destroy function, then its struct
        self.libc.free(ctypes.c_void_p(image))

    def _free(self):
        if self.segment is None:
            return
        self.xext.XShmDetach(self.display, ctypes.byref(self.segment))
        self.x11.XSync(self.display, 0)
        self.libc.shmdt(ctypes.c_void_p(self.segment.shmaddr))
        self._destroy(self.image)
        self.segment, self.image, self.size = None, None, (0, 0)

    def read(self, window, width, height):
        """The window's top-left ``width`` x ``height`` pixels (bytes, rows of
        ``4 * width``), or None when the server refused (the window went away
        or is smaller now)."""
        if width <= 0 or height <= 0:
            return None
        if width > self.size[0] or height > self.size[1]:
            self._make(max(width, self.size[0]), max(height, self.size[1]))
        head = ctypes.cast(self.image, ctypes.POINTER(_Image)).contents
        head.width, head.height = width, height     # the request's size
        before = getattr(_errors, 'count', 0)
        ok = self.xext.XShmGetImage(self.display, window, self.image, 0, 0, ALL_PLANES)
        if not ok or getattr(_errors, 'count', 0) != before:
            return None
        # the server writes its own rows into the segment: each padded to 32 bits
        return ctypes.string_at(self.segment.shmaddr, _row_bytes(width) * height)

    def close(self):
        try:
            self._free()
        finally:
            if self.display:
                self.x11.XCloseDisplay(self.display)
                self.display = None

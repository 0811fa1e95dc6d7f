"""Installs :mod:`exp2_cv2_gui` when ``cv2`` is imported: a meta-path finder
that reacts only to ``import cv2`` (cv2 stays lazy), lets cv2's own loader
make the module, then replaces its HighGUI functions by wrappers that run on
the one GUI thread (see exp2_cv2_gui.py for why)."""
import functools
import sys
import threading

from exp2_cv2_gui import MARKER, SYNC_FUNCTIONS, GuiThread


def patch(cv2):
    """Replace cv2's HighGUI functions by GUI-thread wrappers (idempotent)."""
    if getattr(cv2, MARKER, None) is not None or not hasattr(cv2, 'imshow'):
        return
    import os
    gui = GuiThread(cv2)
    gui.legacy_keys = os.environ.get('OPENCV_LEGACY_WAITKEY') is not None

    def wrap(name, impl):
        real = gui.real.get(name)
        if real is None:
            return

        def wrapper(*args, **kwargs):
            return impl(*args, **kwargs)
        setattr(cv2, name, functools.update_wrapper(wrapper, real))  # keeps name and doc

    wrap('imshow', gui.imshow)
    wrap('waitKey', gui.wait_key)
    wrap('waitKeyEx', gui.wait_key_ex)
    wrap('pollKey', gui.poll_key)
    for name in SYNC_FUNCTIONS:
        wrap(name, functools.partial(gui.call, gui.real.get(name)))
    setattr(cv2, MARKER, gui)


class _PatchingLoader(object):
    """Delegates to cv2's own loader, then patches the module it made."""

    def __init__(self, loader):
        self._loader = loader

    def __getattr__(self, name):
        return getattr(self._loader, name)

    def create_module(self, spec):
        return self._loader.create_module(spec)

    def exec_module(self, module):
        self._loader.exec_module(module)
        try:
            patch(sys.modules.get(module.__name__, module))
        except Exception as exc:  # never break ``import cv2`` itself
            sys.stderr.write('[cv2 GUI thread] not enabled: %r\n' % (exc,))


class _Cv2Finder(object):
    """Meta-path finder that only reacts to ``import cv2`` (cv2 stays lazy)."""

    def __init__(self):
        self._local = threading.local()

    def find_spec(self, name, path=None, target=None):
        if name != 'cv2' or getattr(self._local, 'busy', False):
            return None
        self._local.busy = True
        try:
            for finder in sys.meta_path:
                if finder is self or not hasattr(finder, 'find_spec'):
                    continue
                spec = finder.find_spec(name, path, target)
                if spec is not None:
                    break
            else:
                return None
        finally:
            self._local.busy = False
        if spec.loader is not None:
            spec.loader = _PatchingLoader(spec.loader)
        return spec


def install():
    """Patch cv2 when it gets imported (or now, if it already is)."""
    if 'cv2' in sys.modules:
        patch(sys.modules['cv2'])
    elif not any(isinstance(f, _Cv2Finder) for f in sys.meta_path):
        sys.meta_path.insert(0, _Cv2Finder())

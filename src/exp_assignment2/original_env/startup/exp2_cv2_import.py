"""Installs :mod:`exp2_cv2_gui` when ``cv2`` is imported (cv2 stays lazy):
its HighGUI functions are replaced by wrappers that run on the one GUI
thread (see exp2_cv2_gui.py for why)."""
import functools

from exp2_cv2_gui import MARKER, SYNC_FUNCTIONS, GuiThread
from exp2_import_patch import patch_on_import


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


def install():
    """Patch cv2 when it gets imported (or now, if it already is)."""
    patch_on_import('cv2', patch, 'cv2 GUI thread')

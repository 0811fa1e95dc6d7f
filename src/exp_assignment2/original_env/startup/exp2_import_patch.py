"""Patch a module when it gets imported, without importing it first.

:func:`patch_on_import` puts a meta-path finder first that reacts only to
the one module name, lets the module's own finder and loader make it, then
calls the patch on the new module. A module already imported is patched at
once. A patch that fails writes one line and leaves the module as it was:
the import itself never breaks.
"""
import sys
import threading


class _PatchingLoader(object):
    """Delegates to the module's own loader, then patches what it made."""

    def __init__(self, loader, patch, label):
        self._loader, self._patch, self._label = loader, patch, label

    def __getattr__(self, name):
        return getattr(self._loader, name)

    def create_module(self, spec):
        return self._loader.create_module(spec)

    def exec_module(self, module):
        self._loader.exec_module(module)
        try:
            self._patch(sys.modules.get(module.__name__, module))
        except Exception as exc:  # never break the import itself
            sys.stderr.write('[%s] not enabled: %r\n' % (self._label, exc))


class _Finder(object):
    """Meta-path finder for one module name (it stays lazy)."""

    def __init__(self, name, patch, label):
        self.name, self._patch, self._label = name, patch, label
        self._local = threading.local()

    def find_spec(self, name, path=None, target=None):
        if name != self.name or getattr(self._local, 'busy', False):
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
            spec.loader = _PatchingLoader(spec.loader, self._patch, self._label)
        return spec


def patch_on_import(name, patch, label):
    """Call ``patch(module)`` when ``name`` is imported (now, if it is).
    ``label`` names the patch in the line a failure writes."""
    if name in sys.modules:
        patch(sys.modules[name])
    elif not any(isinstance(f, _Finder) and f.name == name for f in sys.meta_path):
        sys.meta_path.insert(0, _Finder(name, patch, label))

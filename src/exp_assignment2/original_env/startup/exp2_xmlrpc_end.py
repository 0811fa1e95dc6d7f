"""A node's XML-RPC thread ends when rospy shuts down, as under Python 2.

rospy's ``XmlRpcNode.shutdown`` closes the server's socket and lets its
thread notice. Under Python 2 it did: ``select`` on the closed socket
raised, ``XmlRpcNode._run`` saw ``is_shutdown`` and the thread ended. Under
Python 3, ``serve_forever`` polls through ``selectors``, which reports the
closed descriptor as ready; ``accept`` then fails, ``serve_forever`` swallows
the error and polls again: one core at 100 % for as long as the process
lives. Code written for the original often lives on after SIGINT (a
``while`` loop around ``time.sleep``, which rospy lets run) until roslaunch
sends SIGTERM 15 s later, so every launch's end burnt 15 s of a core.

:func:`install` makes ``shutdown`` also ask ``serve_forever`` to stop (the
flag ``BaseServer.shutdown`` sets, without its wait), so the thread leaves
within the server's poll interval. Nothing else changes.
"""
from exp2_import_patch import patch_on_import

MARKER = '_exp2_ends_serving'


def patch(xmlrpc):
    """Wrap ``xmlrpc.XmlRpcNode.shutdown`` (idempotent)."""
    node = xmlrpc.XmlRpcNode
    if getattr(node.shutdown, MARKER, False):
        return
    shutdown = node.shutdown

    def shutdown_and_stop_serving(self, reason):
        self.is_shutdown = True     # first: _run must not serve again
        server = self.server
        if server is not None:
            server._BaseServer__shutdown_request = True
        shutdown(self, reason)
    shutdown_and_stop_serving.__doc__ = shutdown.__doc__
    setattr(shutdown_and_stop_serving, MARKER, True)
    node.shutdown = shutdown_and_stop_serving


def install():
    """Patch rosgraph.xmlrpc when it gets imported (or now, if it is)."""
    patch_on_import('rosgraph.xmlrpc', patch, 'XML-RPC end')

"""Being told when parameters under a namespace change (the parameter
server's own events, no polling).

rospy subscribes a node to a parameter (``get_param_cached``); the master
then calls the node's ``paramUpdate`` for every change under it, and rospy
updates its cache. Two things are missing for watching a namespace: a
callback, and keys that appear under the namespace after the subscription
(rospy's cache refuses keys it has not seen). :func:`watch_namespace` adds
both, on the process's one cache.
"""
import copy
import threading

import rospy
from rospy.impl.paramserver import get_param_server_cache

_lock = threading.Lock()
_watchers = {}          # resolved namespace + '/' -> [callbacks]


def _install():
    cache = get_param_server_cache()
    if getattr(cache, '_exp2_watching', False):
        return
    original = cache.update

    def update(key, value):
        watchers = [fn for ns, fns in list(_watchers.items()) if (key + '/').startswith(ns)
                    for fn in fns]
        try:
            original(key, value)
        except KeyError:
            if not watchers:
                raise
            cache.set(key, value)      # a key new under a watched namespace
        for fn in watchers:
            fn(key)
    cache.update = update
    cache._exp2_watching = True


def watch_namespace(namespace, callback):
    """Call ``callback(key)`` (in rospy's XML-RPC thread: keep it short) when
    any parameter under ``namespace`` is set. Returns the namespace's value now
    ({} when nothing is set yet)."""
    resolved = rospy.resolve_name(namespace).rstrip('/') + '/'
    with _lock:
        _install()
        _watchers.setdefault(resolved, []).append(callback)
    try:   # a copy: rospy's cache changes in place with every update
        return copy.deepcopy(rospy.get_param_cached(resolved.rstrip('/') or '/'))
    except KeyError:
        return {}


def unwatch_namespace(namespace, callback):
    resolved = rospy.resolve_name(namespace).rstrip('/') + '/'
    with _lock:
        if callback in _watchers.get(resolved, []):
            _watchers[resolved].remove(callback)

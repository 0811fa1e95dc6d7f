"""A run's sandbox: Debian's bubblewrap and the kernel's control groups (no ROS).

Inside, a run has its own network (a loopback of its own: its master is on
11311 and no other run or machine is reachable), its own process numbers
(other runs' processes cannot be seen or signalled), its own ``/tmp``, and a
read-only view of the machine in which the teacher's folder, the other runs
and the home directory are hidden; only its work directory is writable. Its
user is not root. Limits: memory and process count through control groups
(v1 or v2, where this machine lets us make them), the size of any one file
through ``RLIMIT_FSIZE``; wall time is the grader's business. :meth:`Sandbox.kill`
ends every process of the run, whatever it did with its signals: killing the
namespace's first process ends the namespace, and the control group's
members are killed one by one after it.
"""
import os
import shlex
import shutil
import signal
import subprocess
import time

from exp_assignment2.grading.scratch import alive

CGROUP_ROOT = '/sys/fs/cgroup'
FILE_LIMIT = 64 * 1024 * 1024        # bytes: one file (a log) at most
SANDBOX_USER = 1000


class SandboxError(Exception):
    """The sandbox cannot be made on this machine (a grader error)."""


def bwrap_path():
    path = shutil.which('bwrap')
    if not path:
        raise SandboxError('bubblewrap (bwrap) is not installed: apt-get install bubblewrap')
    return path


def _own_cgroup_v1(controller):
    """This process's control group of a v1 controller, as a directory, or None."""
    try:
        with open('/proc/self/cgroup') as f:
            for line in f:
                _, controllers, path = line.rstrip('\n').split(':', 2)
                if controller in controllers.split(','):
                    directory = os.path.join(CGROUP_ROOT, controller, path.lstrip('/'))
                    return directory if os.path.isdir(directory) else None
    except OSError:
        pass
    return None


GROUP_PREFIX = 'exp2-grade-'


def remove_stale_groups(parent):
    """The control groups a grader process made in ``parent`` and left when
    it was killed (SIGKILL leaves no time for :meth:`ControlGroups.remove`):
    what is left in them killed (bubblewrap's ``--die-with-parent`` has
    ended their sandboxes already), then removed. A group is stale when the
    process its name holds is gone; [those removed]."""
    removed = []
    try:
        names = [n for n in os.listdir(parent) if n.startswith(GROUP_PREFIX)]
    except OSError:
        return removed
    for name in names:
        try:
            pid = int(name.rsplit('-', 2)[1])
        except (IndexError, ValueError):
            continue
        if alive(pid):
            continue
        directory = os.path.join(parent, name)
        try:
            with open(os.path.join(directory, 'cgroup.procs')) as f:
                left = [int(line) for line in f if line.strip()]
        except (OSError, ValueError):
            left = []
        for pid in left:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        try:
            os.rmdir(directory)         # once its last process is gone (else: the next time)
            removed.append(name)
        except OSError:
            continue
    return removed


class ControlGroups(object):
    """Memory and process-count limits for one run (best effort: ``notes``
    says which limits hold)."""

    def __init__(self, name, memory_bytes, processes):
        self.dirs, self.notes = [], []
        for controller, settings in (
                ('memory', {'memory.limit_in_bytes': memory_bytes,
                            'memory.memsw.limit_in_bytes': memory_bytes}),
                ('pids', {'pids.max': processes})):
            parent = _own_cgroup_v1(controller)
            if parent is None:
                self.notes.append('no %s limit (no writable control group)' % controller)
                continue
            remove_stale_groups(parent)
            directory = os.path.join(parent, '%s%s-%d-%d' % (GROUP_PREFIX, name, os.getpid(),
                                                              id(self)))
            try:
                os.makedirs(directory, exist_ok=True)
                for key, value in settings.items():
                    path = os.path.join(directory, key)
                    if os.path.exists(path):
                        with open(path, 'w') as f:
                            f.write(str(int(value)))
            except OSError as exc:
                self.notes.append('no %s limit (%s)' % (controller, exc.strerror))
                continue
            self.dirs.append(directory)

    def enter_command(self):
        """Shell words that move the shell into the groups before it execs."""
        return ' && '.join('echo $$ > %s' % shlex.quote(os.path.join(d, 'cgroup.procs'))
                           for d in self.dirs)

    def pids(self):
        found = set()
        for directory in self.dirs:
            try:
                with open(os.path.join(directory, 'cgroup.procs')) as f:
                    found.update(int(line) for line in f if line.strip())
            except OSError:
                pass
        return found

    def _memory_file(self, name):
        """The text of one of the memory controller's files, or None."""
        for directory in self.dirs:
            path = os.path.join(directory, name)
            if os.path.exists(path):
                with open(path) as f:
                    return f.read()
        return None

    def peak_memory(self):
        """Bytes the run used at its peak (None without a memory group)."""
        text = self._memory_file('memory.max_usage_in_bytes')
        return int(text) if text else None

    def oom_killed(self):
        """Did the kernel kill a process of the run for its memory?"""
        for line in (self._memory_file('memory.oom_control') or '').splitlines():
            if line.startswith('oom_kill ') and int(line.split()[1]) > 0:
                return True
        return False

    def remove(self):
        for directory in self.dirs:
            for _ in range(50):
                try:
                    os.rmdir(directory)
                    break
                except OSError:
                    time.sleep(0.1)


def mount_table(work, hidden=(), readonly=(), sockets=None, binds=()):
    """[(path, writable)] of a sandbox's mounts, in :meth:`Sandbox.argv`'s order."""
    found = [('/', False), ('/tmp', True), ('/dev/shm', True), ('/run', True)]
    found += [(p, True) for p in hidden if os.path.isdir(p)]
    found += [(p, False) for p in readonly if os.path.exists(p)]
    found += [(sockets, False)] if sockets else []
    return found + [(target, True) for _, target in binds] + [(work, True)]


def writable_at(path, mounts):
    """Is ``path`` writable in a sandbox of these mounts? The deepest mount
    that holds it says (a nested mount is made after, and over, its parent)."""
    path = os.path.normpath(path)
    return max((m for m in mounts if path == m[0] or path.startswith(m[0].rstrip(os.sep) + os.sep)),
               key=lambda m: len(m[0]))[1]


class Sandbox(object):
    """One run's sandbox: ``work`` writable, ``hidden`` paths emptied,
    ``readonly`` paths put back inside hidden ones, ``sockets`` (a directory of
    the grader's) shown read-only at the same path, ``binds`` (source, target) writable."""

    def __init__(self, name, work, hidden=(), readonly=(), sockets=None, binds=(),
                 memory_mb=3000, processes=512, env=None):
        self.name, self.work = name, os.path.abspath(work)
        self.binds = list(binds)       # (source, target): writable, source of the run's
        self.hidden, self.readonly, self.sockets = list(hidden), list(readonly), sockets
        self.env = dict(env or {})
        self.groups = ControlGroups(name, memory_mb * 1024 * 1024, processes)
        self.proc = None

    def argv(self, command):
        args = [bwrap_path(), '--die-with-parent', '--unshare-pid', '--unshare-net',
                '--unshare-ipc', '--unshare-uts', '--hostname', 'grader',
                '--unshare-user', '--uid', str(SANDBOX_USER), '--gid', str(SANDBOX_USER),
                '--new-session', '--ro-bind', '/', '/', '--dev', '/dev', '--proc', '/proc',
                '--tmpfs', '/tmp', '--tmpfs', '/dev/shm', '--tmpfs', '/run']
        for path in self.hidden:
            if os.path.isdir(path):
                args += ['--tmpfs', path]
        for path in self.readonly:
            if os.path.exists(path):
                args += ['--ro-bind', path, path]
        if self.sockets:
            args += ['--ro-bind', self.sockets, self.sockets]
        for source, target in self.binds:
            args += ['--bind', source, target]
        args += ['--bind', self.work, self.work, '--chdir', self.work, '--clearenv']
        for key, value in sorted(self.env.items()):
            args += ['--setenv', key, str(value)]
        return args + ['--'] + list(command)

    def mounts(self):
        """[(path, writable)] as :meth:`argv` mounts them, later ones over earlier."""
        return mount_table(self.work, self.hidden, self.readonly, self.sockets, self.binds)

    def may_write(self, path):
        """Could a process of the run have written the file at ``path`` (as the
        run sees it)?"""
        return writable_at(path, self.mounts())

    def start(self, command, stdout, stdin=subprocess.PIPE):
        """Start ``command`` in the sandbox (a Popen with text pipes)."""
        inner = 'exec prlimit --fsize=%d -- %s' % (FILE_LIMIT, ' '.join(
            shlex.quote(a) for a in self.argv(command)))
        enter = self.groups.enter_command()
        script = (enter + ' && ' if enter else '') + inner
        self.proc = subprocess.Popen(['/bin/sh', '-c', script], stdin=stdin, stdout=stdout,
                                     stderr=subprocess.STDOUT, text=True, bufsize=1,
                                     start_new_session=True)
        return self.proc

    def kill(self, timeout=10.0):
        """End every process of the run; True when none is left."""
        if self.proc is not None and self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, signal.SIGKILL)
            except OSError:
                pass
        deadline = time.monotonic() + timeout
        while True:
            left = self.groups.pids()
            if not left or time.monotonic() > deadline:
                break
            for pid in left:
                try:
                    os.kill(pid, signal.SIGKILL)
                except OSError:
                    pass
            time.sleep(0.1)
        if self.proc is not None:
            try:
                self.proc.wait(timeout=max(0.1, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                pass
        return not self.groups.pids()

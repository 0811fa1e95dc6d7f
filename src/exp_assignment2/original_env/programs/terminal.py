#!/usr/bin/python3
"""Terminal windows of the original-code shell: ``gnome-terminal``, ``xterm``,
``konsole``, ``terminator``, ``x-terminal-emulator`` (environment.py copies
this file under each name to $EXP2_ORIGINAL_BIN, first on PATH).

Students open nodes in windows of their own (``launch-prefix="xterm -e"``,
``gnome-terminal -x sh -c "..."`` in a start script). Each command runs here
in a window of Debian's xterm on the display (a grading run has its own,
whose windows its page shows), as the program named runs it: gnome-terminal
with its own arguments (:data:`GRAMMARS`; each ``--tab``/``--window`` a
window) returns once its windows are open, as when it hands them to its
server; xterm (its own options), konsole and terminator wait for their
command and end with its exit status (a signal as that signal), where
xterm's own is always 0, so that roslaunch's ``process has died`` line on a
node in a window says how the node ended; a SIGINT or SIGTERM to them
(roslaunch ending its nodes) goes on to the command's process group.

The command runs on a pseudo-terminal of the relay (this file with
``--exp2-relay``, inside the window), which copies its output to the window
and, as if there were no window, to the opener's standard output when that
is a file or a pipe (roslaunch's screen, a node's ``-stdout.log``).
With no DISPLAY, or no xterm, one line and status 1.
"""
import fcntl
import os
import pty
import select
import shlex
import shutil
import signal
import subprocess
import sys
import termios
import tty

RELAY = '--exp2-relay'
FOREGROUND = ('xterm', 'x-terminal-emulator', 'konsole', 'terminator')


class Usage(Exception):
    """A command line the named terminal refuses: the one line it says."""


class Window(object):
    """One window to open: its command (None: a shell), title, geometry, directory."""

    def __init__(self):
        self.command = self.title = self.geometry = self.cwd = None
        self.hold, self.options = False, []     # options: xterm's own, passed as they are


# name -> (options that take the rest as the command, options whose value is
# the command as one string, title, geometry, working directory, hold,
# options that start the next window, other options with a value, flags)
GRAMMARS = {
    'gnome-terminal': (('--', '-x', '--execute'), ('-e', '--command'), ('-t', '--title'),
                       ('--geometry',), ('--working-directory',), (),
                       ('--tab', '--window', '--tab-with-profile', '--window-with-profile'),
                       ('--profile', '--role', '--zoom', '--load-config', '--save-config',
                        '--app-id', '--fd', '--class', '--display', '--name'),
                       ('--hide-menubar', '--show-menubar', '--maximize', '--full-screen',
                        '--active', '-q', '--quiet', '-v', '--verbose', '--disable-factory',
                        '--print-environment', '--preferences', '--wait')),
    'konsole': (('-e',), (), ('--title', '-qwindowtitle'), ('--geometry', '-geometry'),
                ('--workdir',), ('--hold', '--noclose'), (),
                ('--profile', '-p', '--tabs-from-file', '--layout'),
                ('--new-tab', '--nofork', '--separate', '--hide-menubar', '--hide-tabbar',
                 '--fullscreen', '--notransparency', '--show-menubar', '--show-tabbar')),
    'terminator': (('-x', '--execute'), ('-e', '--command'), ('-T', '--title'),
                   ('--geometry',), ('--working-directory',), ('-H', '--hold'), (),
                   ('-g', '--config', '-l', '--layout', '-p', '--profile', '-r', '--role',
                    '-i', '--icon', '-c', '--classname', '--debug-classes',
                    '--debug-methods'),
                   ('-u', '--no-dbus', '--new-tab', '-m', '--maximise', '-M', '--maximize',
                    '-f', '--fullscreen', '-b', '--borderless', '-d', '--debug', '-s',
                    '--hidden', '-v', '--version')),
}


def parse(name, args):
    """([Window], wait?) that ``name ARGS`` opens; raises :class:`Usage`."""
    if name in ('xterm', 'x-terminal-emulator'):
        window = Window()
        if '-e' in args:
            at = args.index('-e')
            window.options, window.command = args[:at], args[at + 1:]
            if not window.command:
                raise Usage('option -e requires a command')
        else:
            window.options = list(args)
        return [window], True
    rest_cmd, string_cmd, title, geometry, cwd, hold, opener, valued, flags = GRAMMARS[name]
    windows, opened, wait, i = [Window()], False, name != 'gnome-terminal', 0
    while i < len(args):
        arg = args[i]
        option, has_value, value = arg.partition('=') if arg.startswith('--') else (arg, '', '')
        if option in rest_cmd:
            windows[-1].command = args[i + 1:]
            if not windows[-1].command:
                raise Usage('%s needs a command after it' % option)
            break
        if len(arg) > 2 and not arg.startswith('--') and arg[:2] in string_cmd + title:
            option, has_value, value = arg[:2], '=', arg[2:]       # -e"CMD", -tTITLE
        if option in string_cmd + title + geometry + cwd + valued or (
                option in opener and option.endswith('profile')):
            if not has_value:
                if i + 1 >= len(args):
                    raise Usage('option %s needs a value' % option)
                i, value = i + 1, args[i + 1]
        elif option not in opener + hold + flags:
            raise Usage('unknown option %s' % arg)
        if option in opener:            # the next window, unless this is the first
            if opened or windows[-1].command is not None:
                windows.append(Window())
            opened = True
        elif option in string_cmd:
            try:
                windows[-1].command = shlex.split(value)
            except ValueError as exc:
                raise Usage('cannot read the command %r: %s' % (value, exc))
        elif option in hold:
            windows[-1].hold = True
        elif option == '--wait':
            wait = True
        elif option == '-p' and value.startswith('tabtitle='):     # konsole's
            windows[-1].title = value.split('=', 1)[1]
        for field, names in (('title', title), ('geometry', geometry), ('cwd', cwd)):
            if option in names:
                setattr(windows[-1], field, value)
        i += 1
    return windows, wait


def real_xterm():
    own = os.path.dirname(os.path.realpath(__file__))
    path = os.pathsep.join(d for d in os.environ.get('PATH', '').split(os.pathsep)
                           if d and os.path.realpath(d) != own)
    return shutil.which('xterm', path=path)


def xterm_argv(xterm, window, log_fd, status_fd):
    """The real xterm's command line for the window, its command through the relay."""
    argv = [xterm] + window.options
    command = window.command or [os.environ.get('SHELL') or '/bin/bash']
    if not set(window.options) & {'-T', '-title'}:        # as xterm titles it
        argv += ['-T', window.title or os.path.basename(command[0])]
    if window.geometry:
        argv += ['-geometry', window.geometry]
    if window.hold:
        argv.append('-hold')
    return argv + ['-e', sys.executable, os.path.realpath(__file__), RELAY, str(log_fd),
                   str(status_fd), '--'] + command


def open_windows(name, windows, wait):
    """Each window open, relayed; with ``wait``, its command's exit status."""
    xterm = real_xterm()
    if xterm is None:
        raise Usage("Debian's xterm is not installed, and it draws this window "
                    '(apt-get install xterm; bash tools/run grade installs it)')
    try:        # where the command's output goes as if there were no window: a log
        log_fd = -1 if os.isatty(1) else os.dup(1)
    except OSError:
        log_fd = -1
    opened = []
    for window in windows:
        read_fd, write_fd = os.pipe()
        fds = tuple(fd for fd in (log_fd, write_fd) if fd >= 0)
        try:
            proc = subprocess.Popen(xterm_argv(xterm, window, log_fd, write_fd), pass_fds=fds,
                                    cwd=window.cwd, stdin=subprocess.DEVNULL,
                                    start_new_session=True)
        except OSError as exc:
            raise Usage('xterm could not start: %s' % (exc.strerror or exc))
        finally:
            os.close(write_fd)
        status = os.fdopen(read_fd)
        line = status.readline()       # the relay's "pid N": the window is open
        if not line.startswith('pid '):
            raise Usage('the window could not be opened (xterm exit %s)' % proc.wait())
        opened.append((proc, status, int(line.split()[1])))
    if not wait:
        return 0
    (proc, status, pid), = opened[:1]
    forward = lambda sig, _frame: _signal_group(pid, sig)     # noqa: E731
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, forward)
    said = status.read().split()       # "exit CODE", when the command has ended
    code = proc.wait() or 1            # xterm's 0 says nothing: the relay did not say it
    if len(said) == 2 and said[0] == 'exit':
        code = int(said[1])
    for other, _, _ in opened[1:]:
        other.wait()
    return code


def _signal_group(pid, sig):
    try:
        os.killpg(pid, sig)
    except OSError:
        pass


def _write_all(fd, data):
    while data:
        data = data[os.write(fd, data):]


def _copy_size(master):
    try:
        size = fcntl.ioctl(0, termios.TIOCGWINSZ, b'\0' * 8)
        fcntl.ioctl(master, termios.TIOCSWINSZ, size)
    except OSError:
        pass


def _copy(fd, outputs):
    """What ``fd`` has now to each output ((fd, also?)); False at its end."""
    try:
        data = os.read(fd, 65536)
    except OSError:          # EIO: nothing holds the command's terminal any more
        data = b''
    for out, lines in outputs:
        try:
            if out >= 0:
                _write_all(out, data.replace(b'\r\n', b'\n') if lines else data)
        except OSError:      # the window gone, the log full: the other goes on
            pass
    return bool(data)


def relay(log_fd, status_fd, command):
    """In the window: ``command`` on a pseudo-terminal, its output to the window
    and to ``log_fd``, the keyboard to it; 'pid N' then 'exit CODE' to
    ``status_fd``. It ends when the command does, as the window's own child."""
    for fd in (log_fd, status_fd):
        if fd >= 0:
            os.set_inheritable(fd, False)
    pid, master = pty.fork()
    if pid == 0:
        for sig in (signal.SIGPIPE, signal.SIGXFSZ):    # Python ignores them; a node must not
            signal.signal(sig, signal.SIG_DFL)
        try:
            os.execvp(command[0], command)
        except OSError as exc:
            sys.stderr.write('%s: %s\n' % (command[0], exc.strerror or exc))
        os._exit(127)
    try:
        _write_all(status_fd, b'pid %d\n' % pid)
    except OSError:
        pass
    _copy_size(master)
    wake_read, wake_write = os.pipe()         # a signal's arrival, seen by select
    os.set_blocking(wake_write, False)
    signal.set_wakeup_fd(wake_write)
    signal.signal(signal.SIGCHLD, lambda *_: None)
    signal.signal(signal.SIGWINCH, lambda *_: _copy_size(master))
    signal.signal(signal.SIGHUP, lambda *_: _signal_group(pid, signal.SIGHUP))  # window closed
    saved = termios.tcgetattr(0) if os.isatty(0) else None
    if saved:
        tty.setraw(0)        # every key to the command's terminal (Ctrl-C: its SIGINT)
    outputs, inputs, status = ((1, False), (log_fd, True)), [master, 0, wake_read], None
    try:
        while status is None and master in inputs:
            for fd in select.select(inputs, [], [])[0]:
                if fd == wake_read:
                    os.read(wake_read, 512)
                    done, raw = os.waitpid(pid, os.WNOHANG)
                    status = raw if done else None
                elif fd == 0:
                    if not _copy(0, ((master, False),)):
                        inputs.remove(0)
                elif not _copy(master, outputs):
                    inputs.remove(master)
        while select.select([master], [], [], 0.1)[0] and _copy(master, outputs):
            pass             # what it wrote last
    finally:
        if saved:
            termios.tcsetattr(0, termios.TCSAFLUSH, saved)
    code = os.waitstatus_to_exitcode(status if status is not None else os.waitpid(pid, 0)[1])
    try:
        _write_all(status_fd, b'exit %d\n' % code)
    except OSError:
        pass
    return code if code >= 0 else 128 - code


def main(argv):
    if len(argv) >= 4 and argv[1] == RELAY and '--' in argv:
        at = argv.index('--')
        return relay(int(argv[2]), int(argv[3]), argv[at + 1:])
    name = os.path.basename(argv[0])
    name = name if name in GRAMMARS or name in FOREGROUND else 'gnome-terminal'
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):   # before the window opens
        signal.signal(sig, lambda number, _: sys.exit(128 + number))
    try:
        windows, wait = parse(name, argv[1:])
        if not os.environ.get('DISPLAY') and '-display' not in windows[0].options:
            raise Usage('no display to open a window on (DISPLAY is not set): run it in '
                        'a desktop session, or under xvfb-run')
        code = open_windows(name, windows, wait)
    except Usage as exc:
        sys.stderr.write('%s: %s\n' % (name, exc))
        return 1
    if code < 0:                         # ended by a signal: end by it too
        signal.signal(-code, signal.SIG_DFL)
        os.kill(os.getpid(), -code)
        return 128 - code
    return code


if __name__ == '__main__':
    sys.exit(main(sys.argv))

"""The first error of a catkin_make log, as one line naming the user's file.

Recognised, whichever comes first in the log:

* the compiler's ``FILE:LINE:COL: error: ...`` (and ``fatal error``);
* CMake's ``CMake Error at FILE:LINE (command):`` block: the file named is
  the first of the user's files its message mentions (genmsg names the
  ``.msg``), else the innermost call of its stack in the user's files
  (``CMakeLists.txt:LINE``), else where CMake stopped;
* catkin_pkg's ``Error(s) in package 'FILE':`` (a bad package.xml);
* the linker's ``undefined reference to ...``, named by the source file of
  the object it was linking.

Anything else: the log's first line that says ``error``. Paths in the
overlay's source space are written as the user's (``to_user``).
"""
import os
import re

_COMPILER = re.compile(r'^(?P<file>[^\s:][^:]*):(?P<line>\d+):(?:\d+:)? (?:fatal )?error: (?P<msg>.*)$')
_CMAKE = re.compile(r'^CMake Error(?: (?:at|in) (?P<file>[^:(]+?)(?::(?P<line>\d+))?(?: \([^)]*\))?)?:\s*(?P<rest>.*)$')
_FRAME = re.compile(r'^\s+(?P<file>\S+):(?P<line>\d+) \((?P<cmd>[^)]*)\)\s*$')
_CATKIN_PKG = re.compile(r"^Error\(s\) in package '(?P<file>[^']+)':")
_UNDEFINED = re.compile(r'undefined reference to (?P<sym>.*)$')
_OBJECT = re.compile(r'CMakeFiles/[^/\s]+\.dir/(?P<src>\S+?)\.o\b')
_CLASS = re.compile(r"^<class '[\w.]+'>: ")
_ANY_ERROR = re.compile(r'\berror\b', re.IGNORECASE)
_QUOTED_PATH = re.compile(r"(/[^\s'\"\]\[,]+)")

MAX_MESSAGE = 300


def one_line(text, limit=MAX_MESSAGE):
    """Whitespace collapsed; cut at ``limit`` characters."""
    text = ' '.join(text.split())
    return text if len(text) <= limit else text[:limit - 1] + '…'


def first_error(log, to_user, source_root=None):
    """``(where, message)`` for the first error in ``log``, or None.

    ``to_user(path)`` returns the user's path for a path of the overlay's
    source space, or None for a path outside the user's package.
    ``source_root``: what CMake's relative paths are relative to.
    """
    lines = log.splitlines()
    for i, line in enumerate(lines):
        for reader in (_compiler, _cmake, _catkin_pkg, _linker):
            found = reader(lines, i, to_user, source_root)
            if found:
                return found
    for line in lines:
        if _ANY_ERROR.search(line):
            return None, one_line(_user_paths(line, to_user))
    return None


def _compiler(lines, i, to_user, source_root):
    match = _COMPILER.match(lines[i])
    if not match:
        return None
    message = _user_paths(_CLASS.sub('', match.group('msg')), to_user)
    where = _where(match.group('file'), match.group('line'), to_user, source_root,
                   keep_outside=False)
    if where is None:   # a generator's error (empy running genmsg) about a user's file
        named = [p for p in _QUOTED_PATH.findall(match.group('msg')) if to_user(p.rstrip('.:'))]
        where = to_user(named[0].rstrip('.:')) if named else _where(
            match.group('file'), match.group('line'), to_user, source_root)
        if message.startswith(where + ': '):
            message = message[len(where) + 2:]
    return where, one_line(message)


def _cmake(lines, i, to_user, source_root):
    match = _CMAKE.match(lines[i])
    if not match:
        return None
    body, frames = [match.group('rest')], []
    for line in lines[i + 1:]:
        if line.startswith('Call Stack'):
            continue
        frame = _FRAME.match(line)
        if frame:
            frames.append(frame)
        elif line.startswith(' ') or not line.strip():
            if frames and not line.strip():
                break
            body.append(line)
        else:
            break
    message = one_line(_user_paths('\n'.join(body), to_user))
    for path in _QUOTED_PATH.findall('\n'.join(body)):
        if to_user(path.rstrip('.:')):
            return _where(path.rstrip('.:'), None, to_user, source_root), message
    for frame in [match] + frames:
        if frame.group('file'):
            where = _where(frame.group('file'), frame.group('line'), to_user, source_root,
                           keep_outside=False)
            if where:
                return where, message
    return _where(match.group('file'), match.group('line'), to_user, source_root), message


def _catkin_pkg(lines, i, to_user, source_root):
    match = _CATKIN_PKG.match(lines[i])
    if not match:
        return None
    body = []
    for line in lines[i + 1:]:
        if not line.strip():
            break
        body.append(line)
    return _where(match.group('file'), None, to_user, source_root), one_line(' '.join(body))


def _linker(lines, i, to_user, source_root):
    match = _UNDEFINED.search(lines[i])
    if not match:
        return None
    where = None
    for line in (lines[i], lines[i - 1] if i else ''):
        obj = _OBJECT.search(line)
        if obj:     # CMakeFiles/<target>.dir/src/x.cpp.o was built from <package>/src/x.cpp
            where = _package_file(obj.group('src'), to_user, source_root)
            break
    return where, 'undefined reference to ' + one_line(match.group('sym'))


def _package_file(relative, to_user, source_root):
    """A path relative to one of the packages of the source space, as the user's."""
    if source_root and os.path.isdir(source_root):
        for package in sorted(os.listdir(source_root)):
            candidate = os.path.join(source_root, package, relative)
            if os.path.exists(candidate) and to_user(candidate):
                return to_user(candidate)
    return relative


def _from_build_dir(relative, source_root):
    """A compiler's path relative to its package's build directory (ccache's
    base_dir makes them so), in the source space; None if there is none."""
    if not (source_root and os.path.isdir(source_root)):
        return None
    build = os.path.join(os.path.dirname(source_root.rstrip('/')), 'build')
    for package in sorted(os.listdir(source_root)):
        candidate = os.path.normpath(os.path.join(build, package, relative))
        if os.path.exists(candidate):
            return candidate
    return None


def _where(path, line, to_user, source_root, keep_outside=True):
    full = path
    if path.startswith('../'):
        full = _from_build_dir(path, source_root) or path
    elif source_root and not path.startswith('/'):
        full = source_root.rstrip('/') + '/' + path
    user = to_user(full)
    if user is None and not keep_outside:
        return None
    where = user or path
    return where + (':' + line if line else '')


def _user_paths(text, to_user):
    return _QUOTED_PATH.sub(lambda m: to_user(m.group(1)) or m.group(1), text)

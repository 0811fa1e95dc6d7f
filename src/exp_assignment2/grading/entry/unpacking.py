"""A submission's files put in a directory of the grader's, safely (no ROS).

Whatever a student hands in is taken as it is, as ``tar`` and ``cp -a``
would, never followed out of it: a symbolic link that stays inside is kept
as the link it is (made relative, so it still points inside the copy); one
that points out (catkin's ``src/CMakeLists.txt ->
/opt/ros/kinetic/share/catkin/cmake/toplevel.cmake``, in every workspace) is
left out with a note, as is a member whose path leaves the archive (``../``,
an absolute path: GNU tar strips or skips them too), a fifo, a device, a
file that cannot be read. What catkin builds (``build/``, ``devel/``,
``install/``) and version control are never copied. Only two things refuse
a submission: an archive that does not unpack at all, and one past the size
or file-count limit. ``submissions.unpack`` takes an entry by its kind (a git
repository through the git reader, which uses the limits here).
"""
import os
import re
import shutil
import stat
import tarfile
import zipfile

MAX_UNPACKED = 200 * 1024 * 1024     # bytes: a submission bigger than this is refused
MAX_MEMBERS = 20000
NOTES_KEPT = 20                      # notes of one kind listed; the rest counted
# what a build or a checkout leaves, at any depth: catkin_make's and catkin
# build's spaces, version control, a Mac's archive folder
SKIPPED = {'.git', '__MACOSX', '.svn', '.hg', 'build', 'devel', 'install', 'build_isolated',
           'devel_isolated', 'install_isolated', 'logs', '.catkin_tools'}


class SubmissionError(Exception):
    """One line saying why a submission cannot be taken at all."""


class Unpacked(object):
    """Where a submission's files are (``root``: past folders that only wrap
    one folder, as a zip of a folder is) and what was left out (``notes``)."""

    def __init__(self, dest):
        self.dest, self.root, self.notes = dest, dest, []
        self._counts = {}

    def leave_out(self, rel, why):
        count = self._counts[why] = self._counts.get(why, 0) + 1
        if count <= NOTES_KEPT:
            self.notes.append('%s: left out: %s' % (rel, why))
        elif count == NOTES_KEPT + 1:
            self.notes.append('... and more left out: %s' % why)

    def find_root(self):
        here = self.dest
        for _ in range(5):
            entries = [e for e in os.listdir(here) if e not in SKIPPED and not e.startswith('.')]
            if len(entries) != 1 or not os.path.isdir(os.path.join(here, entries[0])) or \
                    os.path.islink(os.path.join(here, entries[0])):
                break
            here = os.path.join(here, entries[0])
        self.root = here
        return self


def _parts(rel):
    return [p for p in rel.replace('\\', '/').split('/') if p not in ('', '.')]


def _skipped(rel):
    return any(p in SKIPPED for p in _parts(rel)[:-1]) or (
        _parts(rel) and _parts(rel)[-1] in SKIPPED)


def _inside(root, member_name):
    """The member's path under root, or None if it would leave it."""
    if member_name.startswith('/') or re.match(r'^[A-Za-z]:', member_name):
        return None
    target = os.path.normpath(os.path.join(root, member_name))
    if target != root and not target.startswith(root + os.sep):
        return None
    return target


def _link(dest, target_path, link_text, out, rel):
    """A link at ``target_path`` to where ``link_text`` points, if that is
    inside ``dest`` as written (kept relative); else left out."""
    base = os.path.dirname(target_path)
    resolved = os.path.normpath(os.path.join(base, link_text))
    if os.path.isabs(link_text) or not (resolved == dest or resolved.startswith(dest + os.sep)):
        out.leave_out(rel, 'a link out of the submission (-> %s)' % link_text)
        return None
    os.makedirs(base, exist_ok=True)
    if os.path.lexists(target_path):
        out.leave_out(rel, 'twice in the archive')
        return None
    os.symlink(link_text, target_path)
    return target_path


def _make_links(dest, links, out):
    """The links, made once every file is there (nothing is written through
    one), then each checked where it really leads: a chain that leaves
    ``dest`` once resolved (``a -> .``, ``b -> a/../x``) is removed."""
    made = [(_link(dest, target, text, out, rel), rel, text) for target, text, rel in links]
    made, real = [m for m in made if m[0]], os.path.realpath(dest)
    while True:
        out_of_it = [m for m in made if not _within(real, os.path.realpath(m[0]))]
        if not out_of_it:
            return
        for path, rel, text in out_of_it:
            os.unlink(path)
            out.leave_out(rel, 'a link out of the submission (-> %s)' % text)
        made = [m for m in made if m not in out_of_it]


def _within(dest, path):
    return path == dest or path.startswith(dest + os.sep)


class _Budget(object):
    def __init__(self, limit, what):
        self.limit, self.total, self.what = limit, 0, what

    def take(self, size):
        self.total += size
        if self.total > self.limit:
            raise SubmissionError('%s more than %d MB' % (self.what, self.limit // 2 ** 20))


def _write(src, target, budget):
    os.makedirs(os.path.dirname(target), exist_ok=True)
    with open(target, 'wb') as out:
        while True:      # counted as read: an archive's declared sizes can lie
            chunk = src.read(1 << 20)
            if not chunk:
                break
            budget.take(len(chunk))
            out.write(chunk)


def unpack_zip(path, dest, out, limit):
    budget = _Budget(limit, 'the archive unpacks to')
    with zipfile.ZipFile(path) as archive:
        members = archive.infolist()
        if len(members) > MAX_MEMBERS:
            raise SubmissionError('the archive holds %d files (at most %d)'
                                  % (len(members), MAX_MEMBERS))
        links = []
        for info in members:
            name = info.filename
            target = _inside(dest, name)
            mode = (info.external_attr >> 16) & 0o177777
            if target is None:
                out.leave_out(name, 'a path out of the archive')
            elif _skipped(name):
                continue
            elif stat.S_ISLNK(mode):
                links.append((target, archive.read(info).decode('utf-8', 'replace'), name))
            elif info.is_dir():
                os.makedirs(target, exist_ok=True)
            elif stat.S_IFMT(mode) not in (0, stat.S_IFREG):
                out.leave_out(name, 'not a regular file')
            else:
                with archive.open(info) as src:
                    _write(src, target, budget)
                os.chmod(target, 0o755 if mode & 0o111 else 0o644)
    _make_links(dest, links, out)


def unpack_tar(path, dest, out, limit):
    budget = _Budget(limit, 'the archive unpacks to')
    links = []
    with tarfile.open(path, 'r:*') as archive:
        count = 0
        for member in archive:
            count += 1
            if count > MAX_MEMBERS:
                raise SubmissionError('the archive holds more than %d files' % MAX_MEMBERS)
            target = _inside(dest, member.name)
            if target is None:
                out.leave_out(member.name, 'a path out of the archive')
            elif _skipped(member.name):
                continue
            elif member.issym():
                links.append((target, member.linkname, member.name))
            elif member.islnk():        # a hard link: a copy of a file already unpacked
                source = _inside(dest, member.linkname)
                if source and os.path.isfile(source) and not os.path.islink(source):
                    budget.take(os.path.getsize(source))
                    os.makedirs(os.path.dirname(target), exist_ok=True)
                    shutil.copyfile(source, target)
                else:
                    out.leave_out(member.name, 'a hard link to %s, which is not in it'
                                  % member.linkname)
            elif member.isdir():
                os.makedirs(target, exist_ok=True)
            elif not member.isfile():
                out.leave_out(member.name, 'not a regular file (a device or a fifo)')
            else:
                _write(archive.extractfile(member), target, budget)
                os.chmod(target, 0o755 if member.mode & 0o111 else 0o644)
    _make_links(dest, links, out)


def copy_dir(path, dest, limit=MAX_UNPACKED, out=None):
    """A directory submission copied into ``dest``: links kept when they stay
    inside, what cannot be copied left out (noted in ``out``, an Unpacked)."""
    out = out or Unpacked(dest)
    root = os.path.realpath(path)
    budget = _Budget(limit, 'the submission is')

    def refused(error):
        out.leave_out(os.path.relpath(error.filename or root, root),
                      'cannot be read (%s)' % (error.strerror or error))
    os.makedirs(dest, exist_ok=True)
    links = []
    for dirpath, dirnames, filenames in os.walk(root, onerror=refused):
        rel_dir = os.path.relpath(dirpath, root)
        here = os.path.normpath(os.path.join(dest, rel_dir))
        os.makedirs(here, exist_ok=True)
        walked = []
        for name in sorted(dirnames + filenames):
            full, rel = os.path.join(dirpath, name), os.path.normpath(os.path.join(rel_dir, name))
            if name in SKIPPED:
                continue
            try:
                st = os.lstat(full)
            except OSError as exc:
                out.leave_out(rel, 'cannot be read (%s)' % exc.strerror)
                continue
            if stat.S_ISLNK(st.st_mode):
                real = os.path.realpath(full)
                if _within(root, real):     # kept, relative to where it is in the copy
                    links.append((os.path.join(here, name), os.path.relpath(
                        os.path.join(dest, os.path.relpath(real, root)), here), rel))
                else:
                    out.leave_out(rel, 'a link out of the submission (-> %s)'
                                  % os.readlink(full))
            elif stat.S_ISDIR(st.st_mode):
                walked.append(name)
            elif not stat.S_ISREG(st.st_mode):
                out.leave_out(rel, 'not a regular file (a fifo, a socket or a device)')
            else:
                try:
                    budget.take(st.st_size)
                    shutil.copy2(full, os.path.join(here, name), follow_symlinks=False)
                except OSError as exc:
                    out.leave_out(rel, 'cannot be read (%s)' % exc.strerror)
        dirnames[:] = [d for d in dirnames if d in walked]
    _make_links(os.path.abspath(dest), links, out)
    return out

"""A teacher's folder of submissions, read safely (no ROS).

A submission is a directory, a ``.zip`` or a ``.tar.gz``/``.tgz`` holding
one catkin package at its top or one level down (as students hand them in).
A folder that is itself a package is one submission (a student checking
their own work). The folder is only ever read: archives are unpacked into the
run's own directory, refusing what would escape it (``../``, absolute paths,
links pointing out, devices) and what unpacks to more than a set size.
"""
import os
import re
import shutil
import stat
import tarfile
import zipfile

ARCHIVE_SUFFIXES = ('.zip', '.tar.gz', '.tgz')
MAX_UNPACKED = 200 * 1024 * 1024     # bytes: a submission bigger than this is refused
MAX_MEMBERS = 20000
SKIPPED = {'.git', '__MACOSX', '.svn', '.hg', 'build', 'devel', 'install'}
TEACHER_FILES = {'grading.yaml', 'grading.yml'}


class SubmissionError(Exception):
    """One line saying what is wrong with one submission."""


class Submission(object):
    """One entry of the folder: ``name`` (file name less the archive suffix),
    ``path`` (where it is), ``kind`` (``dir``, ``zip``, ``tar``)."""

    def __init__(self, name, path, kind):
        self.name, self.path, self.kind = name, path, kind

    def __repr__(self):
        return 'Submission(%r, %r)' % (self.name, self.kind)


def safe_name(name):
    """A name usable as a directory (the run's) and in a URL."""
    cleaned = re.sub(r'[^A-Za-z0-9._-]+', '_', name).strip('._') or 'submission'
    return cleaned[:80]


def is_package(path):
    return os.path.isfile(os.path.join(path, 'package.xml'))


def _kind(path):
    lower = path.lower()
    if os.path.isdir(path):
        return 'dir'
    if lower.endswith('.zip'):
        return 'zip'
    if lower.endswith('.tar.gz') or lower.endswith('.tgz'):
        return 'tar'
    return None


def _strip_suffix(name):
    lower = name.lower()
    for suffix in ARCHIVE_SUFFIXES:
        if lower.endswith(suffix):
            return name[:-len(suffix)]
    return name


def discover(folder):
    """(submissions, notes): the folder's submissions, and one line for each
    entry that is not one (SubmissionError for a folder that is neither)."""
    folder = os.path.abspath(folder)
    if not os.path.isdir(folder):
        if _kind(folder) in ('zip', 'tar'):
            return [Submission(_strip_suffix(os.path.basename(folder)), folder,
                               _kind(folder))], []
        raise SubmissionError('%s: no such folder' % folder)
    if is_package(folder):
        return [Submission(os.path.basename(folder), folder, 'dir')], []
    submissions, notes, names = [], [], set()
    for entry in sorted(os.listdir(folder)):
        path = os.path.join(folder, entry)
        if entry.startswith('.') or entry in TEACHER_FILES:
            continue
        kind = _kind(path) if not os.path.islink(path) else None
        if kind is None:
            notes.append('%s: not a submission (a folder, .zip, .tar.gz or .tgz): skipped'
                         % entry)
            continue
        name = safe_name(_strip_suffix(entry))
        while name in names:
            name += '_'
        names.add(name)
        submissions.append(Submission(name, path, kind))
    if not submissions:
        raise SubmissionError('%s: no submissions in it (folders, .zip, .tar.gz or .tgz)'
                              % folder)
    return submissions, notes


def _inside(root, member_name):
    """The member's path under root; SubmissionError if it would leave it."""
    if member_name.startswith('/') or re.match(r'^[A-Za-z]:', member_name) or \
            '\\' in member_name and '..' in member_name:
        raise SubmissionError('the archive holds an absolute path: %s' % member_name)
    target = os.path.normpath(os.path.join(root, member_name))
    if target != root and not target.startswith(root + os.sep):
        raise SubmissionError('the archive holds a path out of it: %s' % member_name)
    return target


def _unpack_zip(path, dest, limit):
    with zipfile.ZipFile(path) as archive:
        members = archive.infolist()
        if len(members) > MAX_MEMBERS:
            raise SubmissionError('the archive holds %d files (at most %d)'
                                  % (len(members), MAX_MEMBERS))
        total = 0
        for info in members:
            target = _inside(dest, info.filename)
            mode = (info.external_attr >> 16) & 0o177777
            if stat.S_ISLNK(mode):
                raise SubmissionError('the archive holds a symbolic link: %s' % info.filename)
            total += info.file_size
            if total > limit:
                raise SubmissionError('the archive unpacks to more than %d MB'
                                      % (limit // 2 ** 20))
            if info.is_dir():
                os.makedirs(target, exist_ok=True)
                continue
            os.makedirs(os.path.dirname(target), exist_ok=True)
            written = 0
            with archive.open(info) as src, open(target, 'wb') as out:
                while True:      # counted as read: a zip's declared sizes can lie
                    chunk = src.read(1 << 20)
                    if not chunk:
                        break
                    written += len(chunk)
                    if total - info.file_size + written > limit:
                        raise SubmissionError('the archive unpacks to more than %d MB'
                                              % (limit // 2 ** 20))
                    out.write(chunk)
            if mode & 0o111:
                os.chmod(target, 0o755)


def _unpack_tar(path, dest, limit):
    with tarfile.open(path, 'r:*') as archive:
        total, count = 0, 0
        for member in archive:
            count += 1
            if count > MAX_MEMBERS:
                raise SubmissionError('the archive holds more than %d files' % MAX_MEMBERS)
            target = _inside(dest, member.name)
            if member.issym() or member.islnk():
                link = member.linkname
                base = os.path.dirname(target) if member.issym() else dest
                resolved = os.path.normpath(os.path.join(base, link))
                if os.path.isabs(link) or not (resolved == dest or
                                               resolved.startswith(dest + os.sep)):
                    raise SubmissionError('the archive holds a link out of it: %s -> %s'
                                          % (member.name, link))
                raise SubmissionError('the archive holds a link: %s -> %s: hand in the file'
                                      % (member.name, link))
            if member.isdir():
                os.makedirs(target, exist_ok=True)
                continue
            if not member.isfile():
                raise SubmissionError('the archive holds a special file: %s' % member.name)
            total += member.size
            if total > limit:
                raise SubmissionError('the archive unpacks to more than %d MB'
                                      % (limit // 2 ** 20))
            os.makedirs(os.path.dirname(target), exist_ok=True)
            src = archive.extractfile(member)
            with src, open(target, 'wb') as out:
                shutil.copyfileobj(src, out)
            os.chmod(target, 0o755 if member.mode & 0o111 else 0o644)


def copy_dir(path, dest, limit):
    """A directory submission copied (links out of it refused, size bounded)."""
    root = os.path.realpath(path)
    total = 0
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in SKIPPED]
        rel = os.path.relpath(dirpath, root)
        os.makedirs(os.path.join(dest, rel), exist_ok=True)
        for name in dirnames + filenames:
            full = os.path.join(dirpath, name)
            if os.path.islink(full):
                real = os.path.realpath(full)
                if not (real == root or real.startswith(root + os.sep)):
                    raise SubmissionError('%s: a link out of the submission (-> %s)'
                                          % (os.path.join(rel, name), os.readlink(full)))
        for name in filenames:
            full = os.path.join(dirpath, name)
            if not os.path.isfile(full):
                continue
            total += os.path.getsize(full)
            if total > limit:
                raise SubmissionError('the submission is larger than %d MB'
                                      % (limit // 2 ** 20))
            shutil.copy2(full, os.path.join(dest, rel, name), follow_symlinks=True)


def unpack(submission, dest, limit=MAX_UNPACKED):
    """Put the submission's files in ``dest`` (created); SubmissionError saying
    why it cannot be (nothing is written outside ``dest``)."""
    dest = os.path.abspath(dest)
    os.makedirs(dest, exist_ok=True)
    try:
        if submission.kind == 'dir':
            copy_dir(submission.path, dest, limit)
        elif submission.kind == 'zip':
            _unpack_zip(submission.path, dest, limit)
        else:
            _unpack_tar(submission.path, dest, limit)
    except (zipfile.BadZipFile, tarfile.TarError, EOFError, OSError) as exc:
        raise SubmissionError('the archive does not unpack: %s' % (exc,))
    return find_package(dest)


def find_package(root):
    """The one catkin package's directory in ``root`` (at the top or one level
    down, past folders that hold just one folder); SubmissionError for none or two."""
    here = root
    for _ in range(3):        # a zip of a folder of a folder: look through single folders
        if is_package(here):
            return here
        entries = [e for e in os.listdir(here) if e not in SKIPPED and not e.startswith('.')]
        dirs = [e for e in entries if os.path.isdir(os.path.join(here, e))]
        packages = [d for d in dirs if is_package(os.path.join(here, d))]
        if len(packages) > 1:
            raise SubmissionError('two packages in one submission: %s'
                                  % ', '.join(sorted(packages)))
        if packages:
            return os.path.join(here, packages[0])
        if len(dirs) == 1 and len(entries) == 1:
            here = os.path.join(here, dirs[0])
            continue
        break
    for dirpath, dirnames, filenames in os.walk(root):   # deeper: name them, refuse
        dirnames[:] = [d for d in dirnames if d not in SKIPPED]
        if 'package.xml' in filenames:
            raise SubmissionError('no package.xml at the top or one level down (one is at %s)'
                                  % os.path.relpath(dirpath, root))
    raise SubmissionError('no package.xml in it: a submission is one catkin package')


def package_name(package_dir):
    """The package's name from its package.xml (the folder's name if unreadable)."""
    try:
        with open(os.path.join(package_dir, 'package.xml'), errors='replace') as f:
            match = re.search(r'<name>\s*([^<\s]+)\s*</name>', f.read())
    except OSError:
        match = None
    return match.group(1) if match else os.path.basename(package_dir)

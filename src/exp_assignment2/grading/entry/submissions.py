"""A teacher's folder of submissions, read safely (no ROS).

Every entry of the folder is one submission, whatever it is: a directory, a ``.zip`` or a tar
archive (``.tar.gz``, ``.tgz``, ``.tar``, ``.tar.bz2``, ``.tar.xz``) holding what the student
handed in (one package, several, a whole catkin workspace, a repository of the course), and
anything else (a loose file, a fifo, a link, another kind of archive) gets a row and a verdict
saying why it could not be taken: one entry never costs the teacher the others. A folder that is
itself a package is one submission (a student checking their own work). The folder is only ever
read: what is in an entry is put in the run's own directory by
:mod:`~exp_assignment2.grading.entry.unpacking`; which packages it holds, and which of them a run
builds, is :mod:`~exp_assignment2.grading.entry.packages`' to say.
"""
import os
import re
import tarfile
import zipfile

from exp_assignment2.grading.entry import git_entries
from exp_assignment2.grading.entry.unpacking import MAX_UNPACKED, SKIPPED, SubmissionError, \
    Unpacked, copy_dir  # noqa: F401 (the grader's one door to them)
from exp_assignment2.grading.entry.unpacking import unpack_tar, unpack_zip

ARCHIVE_SUFFIXES = ('.zip', '.tar.gz', '.tgz', '.tar', '.tar.bz2', '.tbz2', '.tar.xz', '.txz')
OTHER_ARCHIVES = ('.rar', '.7z', '.gz', '.bz2', '.xz', '.zst')
TEACHER_FILES = {'grading.yaml', 'grading.yml'}


class Submission(object):
    """One entry of the folder: ``name`` (file name less the archive suffix),
    ``path`` (where it is), ``kind`` (``dir``, ``zip``, ``tar``, ``git``: a
    folder that is a git repository, graded at ``commit``, chosen by
    :func:`~exp_assignment2.grading.entry.git_entries.choose`; or ``other``:
    ``why`` says what it is and why it cannot be graded)."""

    def __init__(self, name, path, kind, why=None, commit=None):
        self.name, self.path, self.kind, self.why = name, path, kind, why
        self.commit = commit

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
        return 'git' if git_entries.is_repository(path) else 'dir'
    if lower.endswith('.zip'):
        return 'zip'
    if any(lower.endswith(s) for s in ARCHIVE_SUFFIXES):
        return 'tar'
    return None


def _strip_suffix(name):
    lower = name.lower()
    for suffix in ARCHIVE_SUFFIXES + OTHER_ARCHIVES:
        if lower.endswith(suffix):
            return name[:-len(suffix)]
    return name


def what_it_is(path):
    """Why an entry that is not a folder or an archive cannot be graded (one line)."""
    import stat
    try:
        st = os.lstat(path)
    except OSError as exc:
        return 'cannot be read (%s)' % exc.strerror
    if stat.S_ISLNK(st.st_mode):
        return 'a link (-> %s), not followed: put the submission itself in the folder' \
            % os.readlink(path)
    if stat.S_ISFIFO(st.st_mode) or stat.S_ISSOCK(st.st_mode) or stat.S_ISCHR(st.st_mode) \
            or stat.S_ISBLK(st.st_mode):
        return 'not a file nor a folder (a fifo, a socket or a device)'
    if path.lower().endswith(OTHER_ARCHIVES):
        return 'an archive the grader does not read (a folder, .zip or .tar.gz it does)'
    if not os.access(path, os.R_OK):
        return 'cannot be read (permission denied)'
    return 'a single file, not a submission (a folder, .zip or .tar.gz of the package)'


def discover(folder):
    """(submissions, notes): one Submission per entry of the folder, those
    that cannot be graded with their ``why`` (SubmissionError for a folder
    that is neither a folder of submissions nor one)."""
    folder = os.path.abspath(folder)
    if not os.path.isdir(folder):
        if os.path.exists(folder) and _kind(folder) in ('zip', 'tar'):
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
        name = safe_name(_strip_suffix(entry))
        while name in names:
            name += '_'
        names.add(name)
        if kind is None:
            why = what_it_is(path)
            notes.append('%s: %s: graded as not built' % (entry, why))
            submissions.append(Submission(name, path, 'other', why))
        else:
            submissions.append(Submission(name, path, kind))
    if not submissions:
        raise SubmissionError('%s: no submissions in it (folders, .zip, .tar.gz or .tgz)'
                              % folder)
    return submissions, notes


def package_name(package_dir):
    """The package's name from its package.xml (the folder's name if unreadable)."""
    try:
        with open(os.path.join(package_dir, 'package.xml'), errors='replace') as f:
            match = re.search(r'<name>\s*([^<\s]+)\s*</name>', f.read())
    except OSError:
        match = None
    return match.group(1) if match else os.path.basename(package_dir)


def unpack(submission, dest, limit=MAX_UNPACKED):
    """The submission's files in ``dest`` (created): an :class:`Unpacked`;
    SubmissionError when it cannot be taken at all (nothing is written
    outside ``dest``)."""
    dest = os.path.abspath(dest)
    os.makedirs(dest, exist_ok=True)
    out = Unpacked(dest)
    try:
        if submission.kind == 'dir':
            copy_dir(submission.path, dest, limit, out)
        elif submission.kind == 'zip':
            unpack_zip(submission.path, dest, out, limit)
        elif submission.kind == 'tar':
            unpack_tar(submission.path, dest, out, limit)
        elif submission.kind == 'git':      # its commit's tree, nothing of .git run
            git_entries.export(submission, dest, out, limit)
        else:
            raise SubmissionError(submission.why or 'not a submission')
    except (zipfile.BadZipFile, tarfile.TarError, EOFError, OSError, ValueError,
            NotImplementedError, RuntimeError) as exc:
        raise SubmissionError('the archive does not unpack: %s' % (exc,))
    return out.find_root()

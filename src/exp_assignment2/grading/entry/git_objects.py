"""A git repository's objects, read with dulwich (no ROS, no ``git``).

A student's repository is untrusted: its ``.git/config`` can name commands
(``core.fsmonitor``, ``core.hooksPath``, ``core.sshCommand``, filter drivers,
``include.path``), and any ``git`` run in it on the teacher's machine could
start them. So the grader never runs ``git`` on a submission: it reads the
objects, as ``git cat-file`` would, and nothing else of ``.git``: ``HEAD``,
``refs/`` and ``packed-refs`` (where the branches point), ``objects/`` (loose
objects, packfiles with their ``.idx``), ``shallow``. Never the config, the
hooks, the index, the attributes, ``objects/info/alternates`` (objects
borrowed from another folder are missing, as they are from a copy of it).

Debian's dulwich reads them (:mod:`~exp_assignment2.grading.entry.git_packs`
for the packs): the objects' formats and names (SHA-1), commits, trees and
tags. Only its modules that read bytes are used (``dulwich.objects``, ``.pack``,
``.object_store``'s ``peel_sha``, ``.lru_cache``), none of which starts a
process or reads a configuration: never ``dulwich.repo.Repo`` (it reads the
config, its commits run hooks), ``porcelain``, ``index`` (a checkout, with
filters) nor a client. The grader's own rules stay here: which files of
``.git`` are read, each only inside it (a link out is refused); references
followed by name only; every object bounded in size before it is inflated,
and checked against its name.
"""
import collections
import os
import re
import zlib

from dulwich.errors import ObjectFormatException
from dulwich.lru_cache import LRUSizeCache
from dulwich.object_store import peel_sha
from dulwich.objects import ShaFile, object_class

from exp_assignment2.grading.entry.git_packs import DAMAGED, MAX_OBJECT, GitError, Pack

HEX = re.compile(r'^[0-9a-f]{40}$')
REF_NAME = re.compile(r'^(HEAD|refs/[A-Za-z0-9._/+@-]+)$')
CACHE_BYTES = 64 * 1024 * 1024     # objects kept decoded (a delta chain's bases)


Commit = collections.namedtuple('Commit', 'sha tree parents time offset subject')
Commit.__doc__ = ("A commit's ``sha``, ``tree``, ``parents``, ``time`` (s since the epoch, the "
                  "committer's), ``offset`` (the committer's zone, minutes east of UTC) and "
                  "``subject`` (its message's first line).")


def _within(root, path):
    return path == root or path.startswith(root + os.sep)


class Repository(object):
    """The objects and references of the repository in ``path/.git``."""

    def __init__(self, path):
        git_dir = os.path.join(path, '.git')
        if os.path.islink(git_dir) or not os.path.isdir(git_dir):
            raise GitError('.git is not a folder of the submission')
        self.root = os.path.realpath(git_dir)
        if not _within(os.path.realpath(path), self.root):
            raise GitError('.git leads out of the submission')
        if os.path.isdir(os.path.join(self.root, 'reftable')):
            raise GitError('a reftable repository (git 2.45\'s format): not read')
        self.objects = os.path.join(self.root, 'objects')
        self.cache = LRUSizeCache(CACHE_BYTES, compute_size=lambda found: len(found[1]))
        self._packs = None
        self.shallow = set((self.read_text('shallow') or '').split())

    def inside(self, path):
        """The real path of a file of ``.git`` (GitError: not a file, or a link out of it)."""
        real = os.path.realpath(path)
        if not _within(self.root, real) or not os.path.isfile(real):
            raise GitError('%s is not a file of the repository' % os.path.relpath(path, self.root))
        return real

    def read_file(self, path, limit=MAX_OBJECT):
        """A file's bytes, if it is a file inside ``.git`` (not through a link out)."""
        real = self.inside(path)
        if os.path.getsize(real) > limit:
            raise GitError('%s is larger than %d MB' % (os.path.basename(path), limit >> 20))
        with open(real, 'rb') as f:
            return f.read()

    def read_text(self, rel):
        path = os.path.join(self.root, rel)
        if not os.path.lexists(path):
            return None
        return self.read_file(path, 1 << 24).decode('utf-8', 'replace')

    def packs(self):
        if self._packs is None:
            folder, self._packs = os.path.join(self.objects, 'pack'), []
            names = sorted(os.listdir(folder)) if os.path.isdir(folder) else []
            for name in names:
                pack = os.path.join(folder, name[:-4] + '.pack')
                if name.endswith('.idx') and os.path.isfile(pack):
                    self._packs.append(Pack(self, self.inside(os.path.join(folder, name)),
                                            self.inside(pack)))
        return self._packs

    def raw(self, sha, chain=0):
        """(type number, bytes) of the object ``sha``, not yet checked against its name."""
        if not HEX.match(sha):      # a name a tag or a commit gave: never a path
            raise GitError('%r is not the name of an object' % sha[:80])
        loose = os.path.join(self.objects, sha[:2], sha[2:])
        if os.path.lexists(loose):     # "TYPE SIZE\0" and the bytes, inflated at most so far
            raw, what = self.read_file(loose), 'object %s' % sha[:12]
            inflater = zlib.decompressobj()
            try:
                whole = inflater.decompress(raw, MAX_OBJECT + 64)
            except zlib.error:
                whole = b''
            header, _, body = whole.partition(b'\0')
            kind, _, size = header.partition(b' ')
            if not inflater.eof or object_class(kind) is None or size != b'%d' % len(body):
                raise GitError('%s: not a git object, or larger than %d MB' % (
                    what, MAX_OBJECT >> 20))
            return object_class(kind).type_num, body
        for pack in self.packs():
            offset = pack.offset(sha)
            if offset is not None:
                return pack.at(offset, chain)
        raise GitError('object %s is not in the repository' % sha[:12])

    def read(self, sha, kind=None):
        """The object ``sha`` as dulwich parses it (a Blob, Tree, Commit or Tag;
        GitError: not there, not it, damaged, or not of ``kind``, b'tree'...)."""
        number, body = self.raw(sha)
        try:
            found = ShaFile.from_raw_string(number, body)
        except DAMAGED + (ObjectFormatException,) as exc:
            raise GitError('object %s is damaged (%s)' % (sha[:12], exc))
        if found.id.decode('ascii') != sha:       # its name, computed from its bytes
            raise GitError('object %s does not hold what its name says' % sha[:12])
        if kind is not None and found.type_name != kind:
            raise GitError('%s is a %s, not a %s' % (sha[:12], found.type_name.decode(),
                                                     kind.decode()))
        return found

    def blob(self, sha):
        """The bytes of the blob ``sha``."""
        return self.read(sha, b'blob').as_raw_string()

    def ref(self, name, depth=0):
        """The commit a reference (``HEAD``, ``refs/...``) names, or None (unborn).
        Read here, not by dulwich's refs, so that a name never leads out of ``.git``
        and a SHA-256 hash is not cut to 40 digits."""
        if depth > 5 or not REF_NAME.match(name) or '..' in name or '//' in name:
            raise GitError('a reference that cannot be followed: %r' % name[:80])
        text = self.read_text(name)
        if text is None:
            for line in (self.read_text('packed-refs') or '').splitlines():
                parts = line.split()
                if len(parts) == 2 and parts[1] == name and HEX.match(parts[0]):
                    return parts[0]
            return None
        text = text.strip()
        if text.startswith('ref:'):
            return self.ref(text[4:].strip(), depth + 1)
        if HEX.match(text):
            return text
        if re.match(r'^[0-9a-f]{64}$', text):
            raise GitError('a SHA-256 repository: not read (the grader reads SHA-1 ones)')
        raise GitError('%s holds neither a commit nor a reference' % name)

    def resolve(self, name):
        """The commit a teacher names: a hash (at least 4 digits of it), a
        tag, a branch (local or ``origin``'s). GitError: none, or several."""
        name = str(name).strip()
        if re.match(r'^[0-9a-fA-F]{4,40}$', name):
            found = self._prefixed(name.lower())
            if len(found) > 1:
                raise GitError('%s names %d objects: give more of the hash' % (name, len(found)))
            if found:
                return self.peel(found.pop())
        for ref in ('refs/tags/', 'refs/heads/', 'refs/remotes/origin/', ''):
            full = ref + name
            if REF_NAME.match(full) and '..' not in full:
                sha = self.ref(full)
                if sha:
                    return self.peel(sha)
        raise GitError('no commit, tag or branch %r in the repository' % name)

    def _prefixed(self, prefix):
        found = {sha for pack in self.packs() for sha in pack.names() if sha.startswith(prefix)}
        folder = os.path.join(self.objects, prefix[:2])
        if os.path.isdir(folder):
            found |= {prefix[:2] + n for n in os.listdir(folder)
                      if (prefix[:2] + n).startswith(prefix) and HEX.match(prefix[:2] + n)}
        return found

    def __getitem__(self, sha):
        """The object ``sha`` (hex bytes), as dulwich's functions on a store ask for it."""
        return self.read(sha.decode('ascii', 'replace'))

    def peel(self, sha):
        """The commit an annotated tag points at (a commit: itself)."""
        peeled = peel_sha(self, sha.encode('ascii'))[1]
        if peeled.type_name != b'commit':
            raise GitError('%s is a %s, not a commit' % (sha[:12], peeled.type_name.decode()))
        return peeled.id.decode('ascii')

    def commit(self, sha):
        """The :class:`Commit` ``sha`` (its parents none at a shallow clone's end)."""
        found = self.read(sha, b'commit')
        tree = (found.tree or b'').decode('ascii', 'replace')
        if not HEX.match(tree):
            raise GitError('commit %s has no tree' % sha[:12])
        # the committer's time: when it was made as it is (the author's if it has none)
        time, zone = found.commit_time, found.commit_timezone
        if time is None:
            time, zone = found.author_time, found.author_timezone
        parents = [] if sha in self.shallow else [
            p.decode('ascii', 'replace') for p in found.parents]
        subject = (found.message or b'').decode('utf-8', 'replace').strip().split('\n')[0][:200]
        return Commit(sha, tree, parents, time or 0, (zone or 0) // 60, subject)

    def tree(self, sha):
        """[(mode, name, sha)] of a tree object."""
        return [(entry.mode, entry.path.decode('utf-8', 'replace'), entry.sha.decode('ascii'))
                for entry in self.read(sha, b'tree').iteritems()]

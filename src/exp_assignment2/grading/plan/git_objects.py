"""A git repository's objects, read in plain Python (no ROS, no ``git``).

A student's repository is untrusted: its ``.git/config`` can name commands
(``core.fsmonitor``, ``core.hooksPath``, ``core.sshCommand``, filter drivers,
``include.path``), and any ``git`` run in it on the teacher's machine could
start them. So the grader never runs ``git`` on a submission: it reads the
objects itself, as ``git cat-file`` would, and nothing else of ``.git``:
``HEAD``, ``refs/`` and ``packed-refs`` (where the branches point),
``objects/`` (loose objects, packfiles with their ``.idx``, deltas of both
kinds), ``shallow``. Never the config, the hooks, the index, the attributes,
``objects/info/alternates`` (objects borrowed from another folder are
missing, as they are from a copy of it). Every file is read only where it
is, inside the repository (a link out of it is refused), and every object
is checked against its name (its SHA-1) and bounded in size.
"""
import hashlib
import os
import re
import zlib

from exp_assignment2.grading.plan.git_packs import MAX_OBJECT, GitError, Pack, _inflate

HEX = re.compile(r'^[0-9a-f]{40}$')
REF_NAME = re.compile(r'^(HEAD|refs/[A-Za-z0-9._/+@-]+)$')
CACHE_BYTES = 64 * 1024 * 1024     # objects kept decoded (a delta chain's bases)


class Commit(object):
    """A commit's ``sha``, ``tree``, ``parents``, ``time`` (s since the epoch,
    the committer's), ``offset`` (the committer's zone, minutes east of UTC)
    and ``subject`` (its message's first line)."""

    def __init__(self, sha, tree, parents, time, offset, subject):
        self.sha, self.tree, self.parents = sha, tree, parents
        self.time, self.offset, self.subject = time, offset, subject


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
        self.cache, self._cached, self._packs = {}, 0, None
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

    def keep(self, key, found):
        if self._cached > CACHE_BYTES:
            self.cache, self._cached = {}, 0
        self.cache[key] = found
        self._cached += len(found[1])

    def packs(self):
        if self._packs is None:
            folder, self._packs = os.path.join(self.objects, 'pack'), []
            names = sorted(os.listdir(folder)) if os.path.isdir(folder) else []
            for name in names:
                pack = os.path.join(folder, name[:-4] + '.pack')
                if name.endswith('.idx') and os.path.isfile(pack):
                    self._packs.append(Pack(self, os.path.join(folder, name), self.inside(pack)))
        return self._packs

    def read(self, sha, chain=0):
        """(type, bytes) of the object ``sha`` (GitError: not there, or not it)."""
        loose = os.path.join(self.objects, sha[:2], sha[2:])
        if os.path.lexists(loose):
            raw = self.read_file(loose)
            try:
                start = zlib.decompressobj().decompress(raw, 64)
            except zlib.error:
                start = b''
            end = start.find(b'\0')
            header = start[:end].split(b' ')
            if end < 0 or len(header) != 2 or not header[1].isdigit():
                raise GitError('object %s: not a git object' % sha[:12])
            if int(header[1]) > MAX_OBJECT:
                raise GitError('object %s is larger than %d MB' % (sha[:12], MAX_OBJECT >> 20))
            body = _inflate(raw, 0, end + 1 + int(header[1]), 'object %s' % sha[:12])[end + 1:]
            found = header[0].decode('ascii', 'replace'), body
        else:
            pack = next((p for p in self.packs() if sha in p.offsets), None)
            if pack is None:
                raise GitError('object %s is not in the repository' % sha[:12])
            found = pack.at(pack.offsets[sha], chain)
        name = hashlib.sha1(b'%s %d\0' % (found[0].encode(), len(found[1])) + found[1])
        if name.hexdigest() != sha:
            raise GitError('object %s does not hold what its name says' % sha[:12])
        return found

    def ref(self, name, depth=0):
        """The commit a reference (``HEAD``, ``refs/...``) names, or None (unborn)."""
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
        found = {sha for pack in self.packs() for sha in pack.offsets if sha.startswith(prefix)}
        folder = os.path.join(self.objects, prefix[:2])
        if os.path.isdir(folder):
            found |= {prefix[:2] + n for n in os.listdir(folder)
                      if (prefix[:2] + n).startswith(prefix) and HEX.match(prefix[:2] + n)}
        return found

    def peel(self, sha):
        """The commit an annotated tag points at (a commit: itself)."""
        for _ in range(10):
            kind, body = self.read(sha)
            if kind == 'commit':
                return sha
            if kind != 'tag' or not body.startswith(b'object '):
                raise GitError('%s is a %s, not a commit' % (sha[:12], kind))
            sha = body[7:47].decode('ascii', 'replace')
        raise GitError('%s: tags of tags of tags' % sha[:12])

    def commit(self, sha):
        kind, body = self.read(sha)
        if kind != 'commit':
            raise GitError('%s is a %s, not a commit' % (sha[:12], kind))
        head, _, message = body.partition(b'\n\n')
        tree, parents, signed = None, [], None
        for line in head.split(b'\n'):
            key, _, value = line.partition(b' ')
            if key == b'tree':
                tree = value.decode('ascii', 'replace')
            elif key == b'parent' and sha not in self.shallow:
                parents.append(value.decode('ascii', 'replace'))
            elif key == b'committer' or (key == b'author' and signed is None):
                signed = value      # the committer's time: when it was made as it is
        time, offset = _when(signed or b'')
        if tree is None or not HEX.match(tree):
            raise GitError('commit %s has no tree' % sha[:12])
        subject = message.decode('utf-8', 'replace').strip().split('\n')[0][:200]
        return Commit(sha, tree, parents, time, offset, subject)

    def tree(self, sha):
        """[(mode, name, sha)] of a tree object."""
        kind, body = self.read(sha)
        if kind != 'tree':
            raise GitError('%s is a %s, not a tree' % (sha[:12], kind))
        out, at = [], 0
        while at < len(body):
            space, nul = body.find(b' ', at), body.find(b'\0', at)
            if space < 0 or nul < space or nul + 21 > len(body):
                raise GitError('tree %s is damaged' % sha[:12])
            mode = int(body[at:space] or b'0', 8)
            out.append((mode, body[space + 1:nul].decode('utf-8', 'replace'),
                        body[nul + 1:nul + 21].hex()))
            at = nul + 21
        return out


def _when(signature):
    """(s since the epoch, minutes east of UTC) of ``Name <mail> 1700000000 +0100``."""
    match = re.search(rb'>\s*(\d+)\s+([+-])(\d\d)(\d\d)\s*$', signature)
    if not match:
        return 0, 0
    minutes = int(match.group(3)) * 60 + int(match.group(4))
    return int(match.group(1)), -minutes if match.group(2) == b'-' else minutes

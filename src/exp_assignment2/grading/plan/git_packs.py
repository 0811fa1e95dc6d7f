"""A git packfile and its index, read in plain Python (no ROS, no ``git``):
the objects of :mod:`~exp_assignment2.grading.plan.git_objects`' repositories
that ``git gc`` or a clone packed, each as a whole object or as a delta on
another (``OFS_DELTA``: by its place in the pack; ``REF_DELTA``: by its name),
every size checked before it is believed.
"""
import mmap
import os
import struct
import zlib

TYPES = {1: 'commit', 2: 'tree', 3: 'blob', 4: 'tag'}
OFS_DELTA, REF_DELTA = 6, 7
MAX_OBJECT = 200 * 1024 * 1024     # bytes of one object (unpacking.MAX_UNPACKED's size)
MAX_CHAIN = 100                    # deltas on deltas before the repository is refused


class GitError(Exception):
    """One line: the repository cannot be read (or not at that commit)."""


def _inflate(data, at, size, what):
    """``size`` bytes inflated from ``data[at:]`` (more or less: GitError)."""
    inflater, out = zlib.decompressobj(), bytearray()
    try:
        while not inflater.eof:
            chunk = data[at:at + (1 << 16)]
            if not chunk:
                raise GitError('%s is cut short' % what)
            at += len(chunk)
            out += inflater.decompress(chunk, size + 1 - len(out))
            if len(out) > size:
                raise GitError('%s is larger than it says' % what)
    except zlib.error as exc:
        raise GitError('%s does not inflate (%s)' % (what, exc))
    if len(out) != size:
        raise GitError('%s is smaller than it says' % what)
    return bytes(out)


def _size(delta, at):
    value, shift = 0, 0
    while True:
        byte = delta[at]
        at += 1
        value |= (byte & 0x7f) << shift
        shift += 7
        if not byte & 0x80:
            return value, at


def apply_delta(base, delta):
    """The object a packfile's delta makes of ``base`` (git's copy/insert code)."""
    try:
        source, at = _size(delta, 0)
        target, at = _size(delta, at)
        if source != len(base) or target > MAX_OBJECT:
            raise GitError('a delta does not fit its base')
        out = bytearray()
        while at < len(delta):
            op = delta[at]
            at += 1
            if op & 0x80:           # copy: offset and size, each byte present if its bit is
                offset = size = 0
                for i in range(4):
                    if op & (1 << i):
                        offset |= delta[at] << (8 * i)
                        at += 1
                for i in range(3):
                    if op & (0x10 << i):
                        size |= delta[at] << (8 * i)
                        at += 1
                size = size or 0x10000
                if offset + size > len(base):
                    raise GitError('a delta copies past its base')
                out += base[offset:offset + size]
            elif op:                # insert the next op bytes
                out += delta[at:at + op]
                at += op
            else:
                raise GitError('a delta with a reserved instruction')
    except IndexError:
        raise GitError('a delta is cut short')
    if len(out) != target:
        raise GitError('a delta makes an object of another size than it says')
    return bytes(out)


class Pack(object):
    """One packfile and its index (version 1 or 2): ``offsets`` {sha: offset}."""

    def __init__(self, repo, idx_path, pack_path):
        self.repo, self.name = repo, os.path.basename(pack_path)
        idx = repo.read_file(idx_path)
        self.offsets = self._index(idx)
        if os.path.getsize(pack_path) < 32:
            raise GitError('%s is not a packfile' % self.name)
        with open(pack_path, 'rb') as f:
            self.data = mmap.mmap(f.fileno(), 0, access=mmap.ACCESS_READ)
        if self.data[:4] != b'PACK':
            raise GitError('%s is not a packfile' % self.name)

    def _index(self, idx):
        try:
            if idx[:4] == b'\xfftOc':
                if struct.unpack_from('>I', idx, 4)[0] != 2:
                    raise GitError('%s: an index version this reader does not know' % self.name)
                count = struct.unpack_from('>256I', idx, 8)[255]
                names, small = 8 + 1024, 8 + 1024 + 24 * count
                large = small + 4 * count
                out = {}
                for i in range(count):
                    offset = struct.unpack_from('>I', idx, small + 4 * i)[0]
                    if offset & 0x80000000:
                        offset = struct.unpack_from('>Q', idx, large + 8 * (offset & 0x7fffffff))[0]
                    out[idx[names + 20 * i:names + 20 * i + 20].hex()] = offset
                return out
            count = struct.unpack_from('>256I', idx, 0)[255]        # version 1
            return {idx[1028 + 24 * i:1048 + 24 * i].hex():
                    struct.unpack_from('>I', idx, 1024 + 24 * i)[0] for i in range(count)}
        except struct.error:
            raise GitError('%s: its index is cut short' % self.name)

    def at(self, offset, chain=0):
        """(type, bytes) of the object at ``offset``, its deltas applied."""
        if chain > MAX_CHAIN:
            raise GitError('%s: a chain of more than %d deltas' % (self.name, MAX_CHAIN))
        cached = self.repo.cache.get((self.name, offset))
        if cached:
            return cached
        data, what = self.data, 'an object of %s' % self.name
        try:
            byte = data[offset]
            kind, size, shift, at = (byte >> 4) & 7, byte & 15, 4, offset + 1
            while byte & 0x80:
                byte = data[at]
                at += 1
                size |= (byte & 0x7f) << shift
                shift += 7
            if size > MAX_OBJECT:
                raise GitError('%s is larger than %d MB' % (what, MAX_OBJECT >> 20))
            if kind == OFS_DELTA:
                byte = data[at]
                at += 1
                back = byte & 0x7f
                while byte & 0x80:
                    byte = data[at]
                    at += 1
                    back = ((back + 1) << 7) | (byte & 0x7f)
                if not 0 < back <= offset:
                    raise GitError('%s: a delta whose base is not in the pack' % what)
                base_kind, base = self.at(offset - back, chain + 1)
                found = base_kind, apply_delta(base, _inflate(data, at, size, what))
            elif kind == REF_DELTA:
                base_kind, base = self.repo.read(data[at:at + 20].hex(), chain + 1)
                found = base_kind, apply_delta(base, _inflate(data, at + 20, size, what))
            elif kind in TYPES:
                found = TYPES[kind], _inflate(data, at, size, what)
            else:
                raise GitError('%s: an object of unknown type %d' % (what, kind))
        except IndexError:
            raise GitError('%s is cut short' % self.name)
        self.repo.keep((self.name, offset), found)
        return found



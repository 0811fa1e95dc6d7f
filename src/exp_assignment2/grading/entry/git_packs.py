"""A git packfile read with dulwich's index and deltas, under the grader's
bounds (no ROS, no ``git``): the objects ``git gc`` or a clone packed, each
whole or a delta on another (``OFS_DELTA``: by its place in the pack;
``REF_DELTA``: by its name).

Two steps stay here because dulwich takes a pack at its word: its
``unpack_object`` inflates an object whole before it compares the size the
pack declares (a few kilobytes of a hostile pack inflate to gigabytes), so
the inflation here stops one byte past it; and its C ``apply_delta``
allocates the size a delta declares and reads a copy's offset bytes without
looking for the delta's end, so those are checked first. A chain of deltas
is bounded, and its base is where the pack can hold it.
"""
import mmap
import os
import struct
import zlib

from dulwich.errors import ApplyDeltaError
from dulwich.pack import OFS_DELTA, REF_DELTA, apply_delta, load_pack_index_file

TYPES = (1, 2, 3, 4)               # commit, tree, blob, tag: dulwich's type numbers
MAX_OBJECT = 200 * 1024 * 1024     # bytes of one object (unpacking.MAX_UNPACKED's size)
MAX_CHAIN = 100                    # deltas on deltas before the repository is refused
# what dulwich raises on bytes that are not what they should be (its C search of an
# index: OverflowError for a count past 2**31, TypeError for a name cut short)
DAMAGED = (ApplyDeltaError, ArithmeticError, AssertionError, IndexError, KeyError, TypeError,
           ValueError, struct.error)


class GitError(Exception):
    """One line: the repository cannot be read (or not at that commit)."""


def inflate(data, at, size, what):
    """``size`` bytes inflated from ``data[at:]`` (more or less: GitError),
    never more than ``size + 1`` of them made. A chunk at a time: zlib copies
    what it is given beyond the stream's end (the rest of a pack)."""
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


def _varint(data, at):
    value, shift = 0, 0
    while True:
        byte = data[at]
        at += 1
        value |= (byte & 0x7f) << shift
        shift += 7
        if not byte & 0x80:
            return value, at


def patch(base, delta):
    """``base`` made into the object ``delta`` describes, by dulwich's
    ``apply_delta`` once the delta fits: it starts from ``base``'s size, makes
    at most MAX_OBJECT bytes, and its last command is whole."""
    try:
        source, at = _varint(delta, 0)
        target, at = _varint(delta, at)
    except IndexError:
        raise GitError('a delta is cut short')
    if source != len(base) or target > MAX_OBJECT:
        raise GitError('a delta does not fit its base')
    while at < len(delta):      # a copy is followed by one byte per bit of 0-6, an insert by N
        op = delta[at]
        at += 1 + (bin(op & 0x7f).count('1') if op & 0x80 else op)
    if at != len(delta):
        raise GitError('a delta is cut short')
    try:
        return b''.join(apply_delta(base, delta))
    except ApplyDeltaError as exc:
        raise GitError('a delta that cannot be applied (%s)' % exc)


class Pack(object):
    """One packfile (``pack_path``) and its index (``idx_path``), both real
    paths inside ``repo``'s ``.git``."""

    def __init__(self, repo, idx_path, pack_path):
        self.repo, self.name = repo, os.path.basename(pack_path)
        try:
            with open(idx_path, 'rb') as f:     # mapped: it stays readable once closed
                self.index = load_pack_index_file(idx_path, f)
        except DAMAGED + (OSError,) as exc:
            raise GitError('%s: its index cannot be read (%s)' % (self.name, exc))
        if os.path.getsize(pack_path) < 32:
            raise GitError('%s is not a packfile' % self.name)
        with open(pack_path, 'rb') as f:
            self.data = mmap.mmap(f.fileno(), 0, access=mmap.ACCESS_READ)
        if self.data[:4] != b'PACK':
            raise GitError('%s is not a packfile' % self.name)

    def offset(self, sha):
        """Where the object ``sha`` is in the pack, or None (not in it)."""
        try:
            return self.index.object_offset(sha.encode('ascii'))
        except KeyError:
            return None
        except DAMAGED as exc:
            raise GitError('%s: its index is damaged (%s)' % (self.name, exc))

    def names(self):
        """The hex names of the objects of the pack."""
        try:
            return [sha.decode('ascii') for sha in self.index]
        except DAMAGED as exc:
            raise GitError('%s: its index is damaged (%s)' % (self.name, exc))

    def at(self, offset, chain=0):
        """(type number, bytes) of the object at ``offset``, its deltas applied."""
        if chain > MAX_CHAIN:
            raise GitError('%s: a chain of more than %d deltas' % (self.name, MAX_CHAIN))
        found = self.repo.cache.get((self.name, offset))
        if found:
            return found
        data, what = self.data, 'an object of %s' % self.name
        try:
            byte = data[offset]     # type and size: 3 and 4 bits, then 7 a byte
            kind, size, shift, at = (byte >> 4) & 7, byte & 15, 4, offset + 1
            while byte & 0x80:
                byte = data[at]
                at += 1
                size |= (byte & 0x7f) << shift
                shift += 7
            if size > MAX_OBJECT:
                raise GitError('%s is larger than %d MB' % (what, MAX_OBJECT >> 20))
            if kind == OFS_DELTA:   # the base so many bytes back (git's own varint)
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
                found = base_kind, patch(base, inflate(data, at, size, what))
            elif kind == REF_DELTA:
                base_kind, base = self.repo.raw(data[at:at + 20].hex(), chain + 1)
                found = base_kind, patch(base, inflate(data, at + 20, size, what))
            elif kind in TYPES:
                found = kind, inflate(data, at, size, what)
            else:
                raise GitError('%s: an object of unknown type %d' % (what, kind))
        except IndexError:
            raise GitError('%s is cut short' % self.name)
        self.repo.cache[(self.name, offset)] = found
        return found

"""dulwich reads a student's git objects under the grader's bounds
(grading/entry/git_objects.py, git_packs.py): only its readers are loaded,
never what reads a configuration or runs hooks; an object or a delta larger
than it may be, or than it says, is refused before it is made."""
import os
import struct
import subprocess
import sys
import zlib

import pytest
from dulwich.objects import Blob, ShaFile

from git_helpers import make_repository
from exp_assignment2.grading.entry import git_objects
from exp_assignment2.grading.entry.git_objects import GitError, Repository
from exp_assignment2.grading.entry.git_packs import MAX_OBJECT, inflate, patch

SRC = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(
    __file__)))), 'src')


def test_only_dulwich_readers_are_loaded():
    """Its Repo reads .git/config, its hooks module runs hooks, its porcelain
    and index check out with filters, its client and config start commands."""
    code = ('import sys; from exp_assignment2.grading.entry import git_entries; '
            'print(" ".join(m for m in sys.modules if m.startswith("dulwich")))')
    loaded = subprocess.run([sys.executable, '-c', code], env=dict(os.environ, PYTHONPATH=SRC),
                            stdout=subprocess.PIPE, check=True,
                            universal_newlines=True).stdout.split()
    assert 'dulwich.pack' in loaded and 'dulwich.objects' in loaded
    for name in ('repo', 'hooks', 'porcelain', 'index', 'client', 'config', 'submodule'):
        assert 'dulwich.' + name not in loaded


def varint(value):
    out = bytearray()
    while True:
        out.append(value & 0x7f | (0x80 if value >> 7 else 0))
        value >>= 7
        if not value:
            return bytes(out)


def test_deltas_copy_and_insert_and_are_refused_when_they_do_not_fit():
    base = b'0123456789' * 10
    # source 100, target 15: copy 10 bytes at offset 5, insert 'abcde'
    delta = bytes([100, 15, 0x80 | 0x01 | 0x10, 5, 10, 5]) + b'abcde'
    assert patch(base, delta) == b'5678901234abcde'
    with pytest.raises(GitError):
        patch(base, bytes([100, 15, 0x80 | 0x01 | 0x10, 95, 10]))    # past the base
    with pytest.raises(GitError):
        patch(base, bytes([99, 1, 1]) + b'x')                        # another base
    with pytest.raises(GitError, match='does not fit'):          # more than an object may be
        patch(base, varint(100) + varint(MAX_OBJECT + 1) + bytes([0x80]))
    with pytest.raises(GitError, match='cut short'):             # its offset bytes missing
        patch(base, bytes([100, 15, 0x80 | 0x0f]))


def test_inflating_stops_past_the_size_an_object_says():
    bomb = zlib.compress(b'\0' * (8 << 20)) + b'PACK'
    with pytest.raises(GitError, match='larger than it says'):
        inflate(bomb, 0, 100, 'an object')
    with pytest.raises(GitError, match='smaller than it says'):
        inflate(bomb, 0, 9 << 20, 'an object')
    with pytest.raises(GitError, match='cut short'):
        inflate(bomb[:len(bomb) // 2], 0, 8 << 20, 'an object')
    assert inflate(b'xx' + zlib.compress(b'abc'), 2, 3, 'an object') == b'abc'


def test_a_loose_object_larger_than_the_bound_is_refused(tmp_path, monkeypatch):
    path = str(tmp_path / 'repo')
    make_repository(path, ['2025-03-01T10:00:00+01:00'])
    blob = b'\0' * (2 << 20)
    sha = Blob.from_string(blob).id.decode()
    loose = os.path.join(path, '.git', 'objects', sha[:2], sha[2:])
    os.makedirs(os.path.dirname(loose), exist_ok=True)
    with open(loose, 'wb') as f:
        f.write(zlib.compress(b'blob %d\0' % len(blob) + blob))
    assert Repository(path).blob(sha) == blob
    monkeypatch.setattr(git_objects, 'MAX_OBJECT', 1 << 20)
    with pytest.raises(GitError, match='larger than 1 MB'):
        Repository(path).blob(sha)


@pytest.mark.parametrize('count', [5, 0xffffffff])
def test_an_index_that_claims_more_objects_than_it_holds_is_one_line(tmp_path, count):
    """Its fan-out's counts are the objects it claims: dulwich's search of
    them (in C) and its list of their names stop at the end, in one line."""
    path = str(tmp_path / 'repo')
    make_repository(path, ['2025-03-01T10:00:00+01:00'])
    folder = os.path.join(path, '.git', 'objects', 'pack')
    with open(os.path.join(folder, 'pack-forged.idx'), 'wb') as f:
        f.write(b'\xfftOc' + struct.pack('>I', 2) + struct.pack('>256I', *[count] * 256) +
                b'\x01' * 50)
    with open(os.path.join(folder, 'pack-forged.pack'), 'wb') as f:
        f.write(b'PACK' + bytes(28))
    with pytest.raises(GitError, match='its index is damaged'):
        Repository(path).resolve('abcd')
    with pytest.raises(GitError, match='its index is damaged'):
        Repository(path).blob('ab' * 20)


def test_a_name_a_tag_gives_is_never_a_path(tmp_path):
    """A hostile tag's object: dulwich keeps the bytes it says, the grader
    reads only an object's name."""
    path = str(tmp_path / 'repo')
    make_repository(path, ['2025-03-01T10:00:00+01:00'])
    tag = b'object ../../../../etc/passwd\ntype commit\ntag v1\n\nx\n'
    sha = ShaFile.from_raw_string(4, tag).id.decode()
    loose = os.path.join(path, '.git', 'objects', sha[:2], sha[2:])
    os.makedirs(os.path.dirname(loose), exist_ok=True)
    with open(loose, 'wb') as f:
        f.write(zlib.compress(b'tag %d\0' % len(tag) + tag))
    with pytest.raises(GitError, match='is not the name of an object'):
        Repository(path).peel(sha)

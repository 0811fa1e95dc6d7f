"""Code shared between submissions (issue 42), read: each submission's files
as MOSS's winnowed fingerprints over tokens. Plain Python, no ROS: unit-tested alone.

The fingerprints are PyPI's ``copydetect``'s (``CodeFingerprint``: pygments
tokens with every name turned into one letter and comments and whitespace
dropped, k-grams of them hashed and winnowed), so renamed identifiers,
re-indentation and changed comments change nothing; a fingerprint is a set
member, so reordered functions change nothing either. Only the k-grams' hash
is ours (:func:`kgram_hashes`): copydetect's is Python's ``hash()``, salted
anew in every process, and a profile keeps a template's fingerprints from
one process to the next (:mod:`.template_prints`). Only the code of the
packages a run builds is read (``folders``: a repository's vendored packages,
which nothing graded uses, are nobody's work). How pairs are compared, and
what is left out of both sides of their share, is
:mod:`~exp_assignment2.grading.similarity.pairs`'.
"""
import hashlib
import logging
import os

# copydetect's defaults: a passage of 25 filtered characters (about a line)
# is noise; one of 30 is always found
NOISE, GUARANTEE = 25, 30
WINDOW = GUARANTEE - NOISE + 1
MAX_FILE = 200 * 1024           # bigger files are data, not code a student writes
SKIPPED_DIRS = {'.git', 'build', 'devel', '__pycache__', 'node_modules', '.svn'}
# file ending -> pygments language; a launch file is XML, a xacro too
LANGUAGES = {'.py': 'python', '.cpp': 'cpp', '.cc': 'cpp', '.cxx': 'cpp', '.h': 'cpp',
             '.hpp': 'cpp', '.c': 'c', '.launch': 'xml', '.xml': 'xml', '.urdf': 'xml',
             '.xacro': 'xml', '.sdf': 'xml', '.world': 'xml', '.yaml': 'yaml', '.yml': 'yaml'}
# package.xml and CMakeLists.txt are written by catkin_create_pkg: the same in all
IGNORED_FILES = {'package.xml', 'CMakeLists.txt'}
# the k-grams' hash (kgram_hashes): an odd base, then splitmix64's finaliser
_BASE = 0x100000001b3
_MIX = ((30, 0xbf58476d1ce4e5b9), (27, 0x94d049bb133111eb), (31, 0))
# how fingerprints are made: a profile's template fingerprints made otherwise are refused
SCHEME = 'winnow-k%d-w%d-poly64.1' % (NOISE, WINDOW)


def default_base_limit(count, share=0.1):
    """More than this many submissions carry a passage: it is base code
    (MOSS's ``-m``): at least 3, else ``share`` of the class."""
    return max(3, int(share * count))


def language_of(path, head=''):
    """The pygments language of a file to compare, or None (not code we read);
    ``head``: its first line, for a script without an ending."""
    name = os.path.basename(path)
    if name in IGNORED_FILES:
        return None
    ext = os.path.splitext(name)[1].lower()
    if ext in LANGUAGES:
        return LANGUAGES[ext]
    if not ext and head.startswith('#!') and 'python' in head:
        return 'python'
    return None


def code_files(root):
    """[(path relative to root, language)] of the files compared, sorted."""
    out = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIPPED_DIRS
                             and not d.startswith('.'))
        for name in sorted(filenames):
            path = os.path.join(dirpath, name)
            if os.path.islink(path) or not os.path.isfile(path) \
                    or os.path.getsize(path) > MAX_FILE:
                continue
            head = ''
            if '.' not in name:
                with open(path, 'rb') as f:
                    head = f.readline(200).decode('utf-8', 'replace')
            language = language_of(path, head)
            if language:
                out.append((os.path.relpath(path, root), language))
    return out


def kgram_hashes(text, k=NOISE):
    """A 64-bit hash of every ``k`` characters of ``text`` (int64, as
    copydetect's), the same in every process: a polynomial over the code
    points modulo 2**64, its bits mixed by splitmix64's finaliser."""
    import numpy as np
    codes = np.frombuffer(text.encode('utf-32-le'), dtype=np.uint32).astype(np.uint64)
    count = len(codes) - k + 1
    if count <= 0:
        return np.zeros(0, dtype=np.int64)
    out = np.zeros(count, dtype=np.uint64)
    for j in range(k):          # numpy's uint64 arithmetic wraps: modulo 2**64
        out = out * _BASE + codes[j:j + count]
    for shift, factor in _MIX:
        out ^= out >> shift
        out = out * factor if factor else out
    return out.view(np.int64)


def fingerprint(text, rel, language):
    """copydetect's fingerprint of one file's text (None when it has no
    token): its filtering and winnowing over :func:`kgram_hashes`."""
    from copydetect import CodeFingerprint
    from copydetect.utils import filter_code, get_token_coverage, winnow
    logging.getLogger().setLevel(logging.ERROR)     # copydetect warns of every odd file
    filtered, offsets = filter_code(text, rel, language)
    if not filtered:
        return None
    hashes, where = winnow(kgram_hashes(filtered), WINDOW, remove_duplicates=False)
    fp = CodeFingerprint.__new__(CodeFingerprint)   # its attributes, as its __init__ sets them
    fp.filename, fp.raw_code, fp.filtered_code, fp.offsets, fp.k = \
        rel, text, filtered, offsets, NOISE
    fp.hash_idx = {}
    for h, at in zip(hashes.tolist(), where.tolist()):
        fp.hash_idx.setdefault(h, []).append(at)
    fp.hashes = set(fp.hash_idx)
    fp.token_coverage = get_token_coverage(fp.hash_idx, NOISE, len(filtered))
    return fp


class Submission(object):
    """One submission's files' fingerprints: ``files`` {rel: CodeFingerprint};
    ``digest``: one hash of its files' texts (two byte-identical submissions
    have the same; None: no code file); ``reference``: an earlier year's."""

    def __init__(self, name, files, digest=None, reference=False):
        self.name = name
        self.files = files
        self.digest, self.reference = digest, reference
        self.own = set()            # fingerprints beyond template and base code
        self.size = 0               # filtered characters the own fingerprints cover

    @classmethod
    def read(cls, name, root, folders=None, reference=False):
        """The code files under ``root``, only those in ``folders`` (relative
        to it: the packages graded) when given."""
        files, texts = {}, []
        for top in (folders or ['.']):
            base = os.path.normpath(os.path.join(root, top))
            for rel, language in code_files(base):
                rel = os.path.normpath(os.path.join(top, rel))
                with open(os.path.join(root, rel), encoding='utf-8', errors='replace') as f:
                    text = f.read()
                texts.append(hashlib.sha1(text.encode('utf-8', 'replace')).hexdigest())
                fp = fingerprint(text, rel, language)
                if fp is not None:
                    files[rel] = fp
        digest = hashlib.sha1(' '.join(sorted(texts)).encode()).hexdigest() if texts else None
        return cls(name, files, digest, reference)

    def hashes(self):
        out = set()
        for fp in self.files.values():
            out |= fp.hashes
        return out


def raw_range(fp, start, end):
    """(start, end) in the file's own text of filtered characters start..end
    (copydetect's own mapping, as in its ``compare_files``)."""
    offsets = fp.offsets
    if len(offsets) == 0:
        return start, end
    import numpy as np
    at = np.clip(np.searchsorted(offsets[:, 0], [start, end]), 0, offsets.shape[0] - 1)
    shift = offsets[:, 1][at]
    return int(start + shift[0]), int(end + shift[1])


def template_keys(hashes):
    """The template's fingerprints as a profile keeps them, and as they are
    looked for: their low 32 bits (4 bytes each in the profile; a student's
    fingerprint is taken for the template's by chance about once in a million)."""
    return {int(h) & 0xffffffff for h in hashes}


def template_hashes(roots):
    """Every fingerprint of the template folders' code files (:func:`template_keys`)."""
    out = set()
    for root in roots:
        out |= template_keys(Submission.read('template', root).hashes())
    return out


def shared_passages(a, b, hashes=None):
    """[(file of a, file of b, slices in a's text, slices in b's text)]: the
    passages two submissions share beyond template and base code, file by
    file, as (start, end) character ranges of each file's own text."""
    from copydetect.detector import compare_files
    hashes = (a.own & b.own) if hashes is None else hashes
    out = []
    for rel_a, fa in sorted(a.files.items()):
        common_a = fa.hashes & hashes
        if not common_a:
            continue
        for rel_b, fb in sorted(b.files.items()):
            if not (common_a & fb.hashes):
                continue
            ka, kb = _only(fa, common_a), _only(fb, common_a)
            overlap, _, (sa, sb) = compare_files(ka, kb)
            if overlap:
                out.append((rel_a, rel_b, _ranges(sa), _ranges(sb)))
    return out


def _only(fp, hashes):
    """A copy of ``fp`` that keeps only the fingerprints in ``hashes``."""
    import copy
    out = copy.copy(fp)
    out.hashes = fp.hashes & hashes
    out.hash_idx = {h: i for h, i in fp.hash_idx.items() if h in out.hashes}
    return out


def _ranges(slices):
    return [(int(s), int(e)) for s, e in zip(slices[0], slices[1])]

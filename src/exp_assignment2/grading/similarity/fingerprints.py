"""Code shared between submissions (issue 42): MOSS's winnowing over tokens,
with template and base code left out. Plain Python, no ROS: unit-tested alone.

The fingerprints are PyPI's ``copydetect``'s (``CodeFingerprint``: pygments
tokens with every name turned into one letter and comments and whitespace
dropped, k-grams of them hashed and winnowed), so renamed identifiers,
re-indentation and changed comments change nothing; a fingerprint is a set
member, so reordered functions change nothing either. What is ours is the
scale: an inverted index (fingerprint -> submissions) so that only pairs that
share a fingerprint are compared, as MOSS does, and the two kinds of code
that never count:

- the template's (``--template``: the assignment's package, earlier labs);
- base code: a fingerprint found in more submissions than ``base_limit``
  (MOSS's ``-m``), e.g. a course file most students carry but nobody handed in
  as a template. Its passages are reported, so the teacher sees what was left out.

A pair's score is its shared code (tokens covered by fingerprints both have,
beyond template and base) as a share of the smaller submission's code beyond
the template. It is for a person to read, never a verdict.
"""
import collections
import io
import itertools
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


def fingerprint(text, rel, language):
    """copydetect's fingerprint of one file's text (None when it has no token)."""
    from copydetect import CodeFingerprint
    logging.getLogger().setLevel(logging.ERROR)     # copydetect warns of every odd file
    fp = CodeFingerprint(rel, NOISE, WINDOW, filter=True, language=language,
                         fp=io.StringIO(text))
    return fp if fp.filtered_code else None


class Submission(object):
    """One submission's files' fingerprints: ``files`` {rel: CodeFingerprint}."""

    def __init__(self, name, files):
        self.name = name
        self.files = files
        self.own = set()            # fingerprints beyond template (then base) code
        self.size = 0               # filtered characters the own fingerprints cover

    @classmethod
    def read(cls, name, root):
        files = {}
        for rel, language in code_files(root):
            with open(os.path.join(root, rel), encoding='utf-8', errors='replace') as f:
                fp = fingerprint(f.read(), rel, language)
            if fp is not None:
                files[rel] = fp
        return cls(name, files)

    def hashes(self):
        out = set()
        for fp in self.files.values():
            out |= fp.hashes
        return out


def _drop(fp, hashes):
    """``fp`` without the fingerprints in ``hashes`` (in place)."""
    gone = fp.hashes & hashes
    if gone:
        fp.hashes = fp.hashes - gone
        fp.hash_idx = {h: i for h, i in fp.hash_idx.items() if h not in gone}


def _coverage(fp, hashes):
    """Filtered characters of ``fp`` covered by its fingerprints in ``hashes``."""
    starts = sorted(int(i) for h in hashes for i in fp.hash_idx.get(h, ()))
    covered, end = 0, -1
    for start in starts:
        covered += max(0, start + fp.k - max(start, end))
        end = max(end, start + fp.k)
    return covered


class Result(object):
    """What ``compare`` found: ``pairs`` [(share, shared, a, b)] best first,
    ``base`` {fingerprint: (carriers, submission name, file, the
    passage's text)} and the settings used."""

    def __init__(self, submissions, pairs, base, base_limit, template_count):
        self.submissions = submissions
        self.pairs = pairs
        self.base = base
        self.base_limit = base_limit
        self.template_count = template_count

    def top_for(self):
        """{name: (share, other name)} of each submission's highest pair."""
        out = {}
        for share, _, a, b in self.pairs:       # best first: the first seen is the top
            out.setdefault(a, (share, b))
            out.setdefault(b, (share, a))
        return out


def compare(submissions, template_hashes=(), base_limit=None):
    """Every pair of ``submissions`` (``Submission``) that shares code beyond
    template and base code, scored; a ``Result``."""
    template_hashes = set(template_hashes)
    if base_limit is None:
        base_limit = default_base_limit(len(submissions))
    index = collections.defaultdict(list)       # fingerprint -> submissions carrying it
    for number, sub in enumerate(submissions):
        for fp in sub.files.values():
            _drop(fp, template_hashes)
        sub.size = sum(_coverage(fp, fp.hashes) for fp in sub.files.values())
        for h in sub.hashes():
            index[h].append(number)
    base = {}
    for h, carriers in index.items():
        if len(carriers) > base_limit:
            base[h] = len(carriers)
    base_set = set(base)
    for sub in submissions:
        sub.own = sub.hashes() - base_set
    base = _describe_base(submissions, base)
    shared = collections.defaultdict(set)        # (i, j) -> fingerprints both own
    for h, carriers in index.items():
        if h not in base_set and len(carriers) > 1:
            for pair in itertools.combinations(carriers, 2):
                shared[pair].add(h)
    pairs = []
    for (i, j), hashes in shared.items():
        a, b = submissions[i], submissions[j]
        covered = min(sum(_coverage(fp, hashes) for fp in s.files.values()) for s in (a, b))
        smaller = min(a.size, b.size) or 1
        first, second = sorted((a.name, b.name))     # one name for a pair's anchor
        pairs.append((min(1.0, covered / float(smaller)), covered, first, second))
    pairs.sort(key=lambda p: (-p[0], -p[1], p[2], p[3]))
    return Result(submissions, pairs, base, base_limit, len(template_hashes))


def _describe_base(submissions, base):
    """{fingerprint: (carriers, submission, file, its text)}: where a
    base passage is seen first, for the report's list of what was left out."""
    out = {}
    for sub in submissions:
        for rel, fp in sorted(sub.files.items()):
            for h in fp.hashes & set(base):
                if h not in out:
                    start = int(fp.hash_idx[h][0])
                    raw_start, raw_end = raw_range(fp, start, start + fp.k)
                    out[h] = (base[h], sub.name, rel, fp.raw_code[raw_start:raw_end])
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


def template_hashes(roots):
    """Every fingerprint of the template folders' code files."""
    out = set()
    for root in roots:
        out |= Submission.read('template', root).hashes()
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

"""Code shared between submissions (issue 42), compared: which pairs share
code that is theirs, and how much of it. Plain Python, no ROS.

As MOSS does, an inverted index (fingerprint -> submissions) finds the pairs
that share a fingerprint; only those are compared. What the whole class
shares is nobody's copy, and is left out of **both sides** of a pair's share:

- the template's code (``--template``: the assignment's package, earlier labs;
  or the profile's fingerprints of it, :mod:`.template_prints`);
- base code: a fingerprint the class carries in more than ``base_limit`` of
  its submissions (MOSS's ``-m``), e.g. a course file most students carry but
  nobody handed in as a template, or the template itself when it was not
  given. Byte-identical submissions count once here, so that a ring of copies
  does not make its own code base code. Its passages are reported.

A pair's share is the code both own (fingerprints beyond template and base
code) over the smaller one's own code (at least ``MIN_OWN`` characters: two
submissions of a few lines of their own do not read 100 % on one line).
Byte-identical submissions with code of their own read 100 %, ``identical``.
A class too small to tell base code (fewer than twice the submissions a
passage needs to be base code: 8 by default), with no template, gets no
figure (``too_small``): what a few submissions share is as likely the
course's files as a copy, and every pair would read as one.
References (``--reference``: earlier years' submissions) are compared with the
class, never among themselves, and do not count for base code. A share is
for a person to read, never a verdict.
"""
import collections
import itertools

from exp_assignment2.grading.similarity.fingerprints import default_base_limit, raw_range

MIN_OWN = 400       # filtered characters (about 15 lines of Python) a share is at least of

Pair = collections.namedtuple('Pair', 'share shared a b identical sizes')
Pair.__doc__ = ('A pair: ``share`` (0..1), ``shared`` (token characters both own), the two '
                'names (sorted), ``identical`` (byte for byte), ``sizes`` (their own code).')


def _drop(fp, keys):
    """``fp`` without the template's fingerprints (``keys``: their low 32 bits; in place)."""
    gone = {h for h in fp.hashes if h & 0xffffffff in keys}
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


def covered(sub, hashes):
    return sum(_coverage(fp, hashes) for fp in sub.files.values())


class Result(object):
    """What ``compare`` found: ``pairs`` [Pair] best first, ``base``
    {fingerprint: (carriers, submission name, file, the passage's text)},
    ``empty`` (the class's submissions with no code of their own), the
    references' names, the settings used and ``too_small`` (no figure to give)."""

    def __init__(self, submissions, pairs, base, base_limit, template_count, empty=(),
                 references=(), too_small=False):
        self.submissions = submissions
        self.pairs = pairs
        self.base = base
        self.base_limit = base_limit
        self.template_count = template_count
        self.empty = list(empty)
        self.references = list(references)
        self.too_small = too_small

    def top_for(self):
        """{name: (share, other name)} of each submission's highest pair."""
        out = {}
        for pair in self.pairs:       # best first: the first seen is the top
            out.setdefault(pair.a, (pair.share, pair.b))
            out.setdefault(pair.b, (pair.share, pair.a))
        return out

    def pair_count(self):
        """Pairs compared: the class's among themselves, and each with each reference."""
        count = len(self.submissions) - len(self.references)
        return count * (count - 1) // 2 + count * len(self.references)


def _base(everyone, index, base_limit):
    """{fingerprint: carriers} carried by more than ``base_limit`` distinct
    submissions of the class (identical ones once; references not counted)."""
    base = {}
    for h, carriers in index.items():
        if len(carriers) <= base_limit:
            continue
        distinct = {everyone[i].digest or ('alone', i) for i in carriers
                    if not everyone[i].reference}
        if len(distinct) > base_limit:
            base[h] = len(carriers)
    return base


def too_small(submissions, base_limit):
    """Whether a class of ``submissions`` is too small to tell base code:
    fewer distinct ones (identical ones once) than twice what base code needs."""
    distinct = {s.digest or ('alone', n) for n, s in enumerate(submissions)}
    return len(distinct) < 2 * (base_limit + 1)


def compare(submissions, template_keys=(), base_limit=None, references=()):
    """Every pair of ``submissions`` (``fingerprints.Submission``), and of each
    with each of ``references``, that shares code of its own; a ``Result``.
    ``template_keys``: the template's fingerprints (``fingerprints.template_keys``)."""
    template_keys = set(template_keys)
    for sub in references:
        sub.reference = True
    everyone = list(submissions) + list(references)
    if base_limit is None:
        base_limit = default_base_limit(len(submissions))
    index = collections.defaultdict(list)       # fingerprint -> submissions carrying it
    for number, sub in enumerate(everyone):
        for fp in sub.files.values():
            _drop(fp, template_keys)
        for h in sub.hashes():
            index[h].append(number)
    base = _base(everyone, index, base_limit)
    base_set = set(base)
    for sub in everyone:
        sub.own = sub.hashes() - base_set
        sub.size = covered(sub, sub.own)
    shared = collections.defaultdict(set)        # (i, j) -> fingerprints both own
    for h, carriers in index.items():
        if h not in base_set and len(carriers) > 1:
            for i, j in itertools.combinations(carriers, 2):
                if not (everyone[i].reference and everyone[j].reference):
                    shared[(i, j)].add(h)
    pairs = [_pair(everyone[i], everyone[j], hashes) for (i, j), hashes in shared.items()]
    pairs.sort(key=lambda p: (-p.share, -p.shared, p.a, p.b))
    empty = [s.name for s in submissions if not s.own]
    return Result(everyone, pairs, _describe_base(everyone, base), base_limit,
                  len(template_keys), empty, [s.name for s in references],
                  not template_keys and too_small(submissions, base_limit))


def _pair(a, b, hashes):
    first, second = sorted((a.name, b.name))     # one name for a pair's anchor
    sizes = (a.size, b.size) if first == a.name else (b.size, a.size)
    if a.digest is not None and a.digest == b.digest:
        return Pair(1.0, a.size, first, second, True, sizes)
    both = min(covered(a, hashes), covered(b, hashes))
    share = min(1.0, both / float(max(min(a.size, b.size), MIN_OWN)))
    return Pair(share, both, first, second, False, sizes)


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

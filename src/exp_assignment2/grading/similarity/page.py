"""The similarity report (issue 42): ``similarity.html`` (pairs ranked, a
histogram of all pairs, the shared passages side by side), ``similarity.json``
for scripts, and a column of each submission's highest pair in ``index.html``.
Made from a :class:`~exp_assignment2.grading.similarity.pairs.Result`; no ROS.
Every student text is escaped: a file may hold anything. A class too small to
tell the course's code, with no template, has its passages and no figure.
"""
import collections
import json
import os
import re

from exp_assignment2.grading.similarity import fingerprints as similarity
from exp_assignment2.grading.similarity import pairs as pairs_
from exp_assignment2.grading.report.html import IMAGES_JS, e as _e, head

DETAILED = 30           # pairs shown side by side (the rest: ranked, in the JSON)
LISTED = 200            # pairs in the page's table
BINS = 20
STYLE = '''body{max-width:1400px}pre{padding:6px;font-size:11px;max-height:40em;margin:0}
mark{background:#ffd54f}.side{display:flex;gap:8px}
.side>div{flex:1;min-width:0}.note{background:#e3f2fd;padding:8px;border-left:4px solid #1976d2}'''

NOT_A_VERDICT = ('Similarity is not a verdict: it changes no verdict and no score. It is a '
                 'list for a person to read, as MOSS and JPlag say of theirs: shared code can '
                 'come from a source both used, from working together as allowed, or from the '
                 'course; and copied code that was rewritten by hand is not found.')


TOO_SMALL = ('%d submissions are too few to tell the course\'s code from a copy: code is '
             'the course\'s when more than %d carry it, and in a class of fewer than %d what '
             'a few share is as likely the course\'s files as a copy. No figure is given; the '
             'passages below are for a person to read. Give the template: --template DIR, or '
             'a profile that carries its fingerprints (grade --fingerprint-template).')
TOO_SMALL_LOG = ('; too few to tell the course\'s code from a copy: no figure (give '
                 '--template, or a profile with its fingerprints)')


def _slug(a, b):
    return 'pair-' + re.sub(r'[^A-Za-z0-9_-]', '_', '%s--%s' % (a, b))


def all_shares(result):
    """Every pair's share, those that share nothing as 0 (they are the bulk
    the histogram shows an outlier against)."""
    return [p.share for p in result.pairs] + [0.0] * (result.pair_count() - len(result.pairs))


def histogram(shares, bins=BINS):
    """Counts of ``shares`` (0..1) in ``bins`` equal bins."""
    counts = [0] * bins
    for share in shares:
        counts[min(bins - 1, int(share * bins))] += 1
    return counts


def histogram_svg(counts, pair_count):
    """An SVG histogram (log-scaled heights, so that one outlier shows beside thousands)."""
    import math
    width, height, left, bottom = 640, 220, 40, 30
    bar = (width - left - 25) / float(len(counts))     # room for the last label
    top = math.log10(max(counts) + 1) or 1
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
             'font-family="sans-serif" font-size="11">' % (width, height),
             '<rect width="100%" height="100%" fill="white"/>']
    for i, count in enumerate(counts):
        h = (height - bottom - 20) * math.log10(count + 1) / top
        x, y = left + i * bar, height - bottom - h
        parts.append('<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="%s"/>' % (
            x + 1, y, bar - 2, h, '#c62828' if i >= len(counts) // 2 else '#1976d2'))
        if count:
            parts.append('<text x="%.1f" y="%.1f" text-anchor="middle">%d</text>'
                         % (x + bar / 2, y - 3, count))
    for i in range(0, len(counts) + 1, len(counts) // 5):
        parts.append('<text x="%.1f" y="%d" text-anchor="middle">%d%%</text>'
                     % (left + i * bar, height - bottom + 14, 100 * i // len(counts)))
    parts.append('<text x="%d" y="%d">code of their own both have, share of the smaller '
                 '(%d pairs; heights on a log scale)</text>'
                 % (left, height - 4, pair_count))
    parts.append('</svg>')
    return ''.join(parts)


def _highlighted(text, ranges):
    """``text`` escaped, with ``ranges`` [(start, end)] marked."""
    out, at = [], 0
    for start, end in sorted(ranges):
        start = max(start, at)
        if end <= start:
            continue
        out.append(_e(text[at:start]) + '<mark>' + _e(text[start:end]) + '</mark>')
        at = end
    out.append(_e(text[at:]))
    return ''.join(out)


def _base_groups(result, shown=3, longest=600):
    """[(file, passages, most carriers, [texts])] of the base code, by file:
    the texts are the file's base passages merged where they touch (a
    fingerprint alone covers 25 token characters: too little to read)."""
    groups = collections.defaultdict(list)
    for h, (carriers, name, rel, _) in result.base.items():
        groups[(rel, name)].append((carriers, h))
    subs = {s.name: s for s in result.submissions}
    out = []
    for (rel, name), items in sorted(groups.items(), key=lambda kv: -len(kv[1])):
        fp = subs[name].files[rel]
        ranges = sorted(similarity.raw_range(fp, int(i), int(i) + fp.k)
                        for _, h in items for i in fp.hash_idx.get(h, ()))
        merged = []
        for start, end in ranges:
            if merged and start <= merged[-1][1]:
                merged[-1][1] = max(merged[-1][1], end)
            else:
                merged.append([start, end])
        merged.sort(key=lambda r: r[0] - r[1])
        texts = [fp.raw_code[a:min(b, a + longest)] for a, b in merged[:shown]]
        out.append((rel, len(items), max(c for c, _ in items), texts))
    return out


def _share(pair, result):
    """A pair's share as the pages write it (no figure: a class too small)."""
    if pair.identical:
        return 'identical'
    return '—' if result.too_small else '%.0f%%' % (100 * pair.share)


def _figure(value, result):
    return None if result.too_small else value


def to_json(result, templates, references=()):
    """What similarity.json holds: settings, every pair, each submission's top, base code."""
    top = {} if result.too_small else result.top_for()
    olds = set(result.references)
    return {
        'note': NOT_A_VERDICT, 'templates': list(templates), 'references': list(references),
        'too_small': result.too_small,
        'min_own': pairs_.MIN_OWN, 'nothing_of_their_own': result.empty,
        'base_limit': result.base_limit, 'template_fingerprints': result.template_count,
        'noise_threshold': similarity.NOISE, 'guarantee_threshold': similarity.GUARANTEE,
        'submissions': [{'name': s.name, 'files': sorted(s.files), 'size': int(s.size),
                         'reference': s.name in olds,
                         'top_share': top.get(s.name, (0.0, None))[0],
                         'top_with': top.get(s.name, (0.0, None))[1]}
                        for s in result.submissions],
        'pairs': [{'a': p.a, 'b': p.b, 'share': _figure(round(float(p.share), 4), result),
                   'shared': int(p.shared),
                   'identical': p.identical, 'own': [int(n) for n in p.sizes],
                   'reference': p.a in olds or p.b in olds}
                  for p in result.pairs],
        'base_code': [{'file': rel, 'carriers': int(carriers), 'first_in': name, 'text': text}
                      for carriers, name, rel, text in sorted(result.base.values())]}


def _pair_section(result, pair):
    subs, a, b = {s.name: s for s in result.submissions}, pair.a, pair.b
    parts = ['<h3 id="%s">%s and %s: %s</h3>' % (_slug(a, b), _e(a), _e(b),
                                                 _share(pair, result))]
    if pair.identical:
        parts.append('<p>The same code files, byte for byte.</p>')
    passages = similarity.shared_passages(subs[a], subs[b])
    if not passages:
        parts.append('<p>No passage to show.</p>')
    for rel_a, rel_b, ranges_a, ranges_b in passages:
        parts.append('<div class="side"><div><b>%s</b>: %s<pre>%s</pre></div><div><b>%s</b>: '
                     '%s<pre>%s</pre></div></div>' % (
                         _e(a), _e(rel_a), _highlighted(subs[a].files[rel_a].raw_code, ranges_a),
                         _e(b), _e(rel_b), _highlighted(subs[b].files[rel_b].raw_code, ranges_b)))
    return ''.join(parts)


def page(result, templates, references=()):
    """similarity.html's text."""
    pairs = result.pairs
    olds = set(result.references)
    parts = [head('Similarity', STYLE, IMAGES_JS),
             '<h1>Code shared between submissions</h1><p class="note">%s</p>' % _e(NOT_A_VERDICT),
             '<p>%d submissions%s, %d pairs sharing code of their own (the others share none). '
             'What the whole class shares is left out of both sides of a share: the template, '
             '%s (%d fingerprints), and base code, a passage found in more than %d submissions '
             '(%d fingerprints, listed below). A share is the code of their own both have, of '
             'the smaller one\'s own code (at least %d token characters).</p>'
             % (len(result.submissions) - len(olds),
                ' and %d of earlier years (%s), compared with the class only' % (
                    len(olds), _e(', '.join(references))) if olds else '', len(pairs),
                _e(', '.join(templates) or 'none given'), result.template_count,
                result.base_limit, len(result.base), pairs_.MIN_OWN),
             '<p class="note">%s</p>' % _e(TOO_SMALL % (
                 len(result.submissions) - len(olds), result.base_limit,
                 2 * (result.base_limit + 1))) if result.too_small else
             '<p><img src="similarity-histogram.svg" alt="histogram of all pairs"></p>']
    if result.empty:
        parts.append('<p>No code of their own beyond template and base code: %s.</p>'
                     % _e(', '.join(result.empty)))
    parts.append('<h2>Pairs, most shared first</h2><table><thead><tr><th>#</th><th>pair</th>'
                 '<th>shared, of the smaller</th><th>shared (token characters)</th>'
                 '<th>their own code</th></tr></thead><tbody>')
    for rank, pair in enumerate(pairs[:LISTED], 1):
        name = '%s and %s' % tuple(_e(n) + (' (earlier year)' if n in olds else '')
                                   for n in (pair.a, pair.b))
        if rank <= DETAILED:
            name = '<a href="#%s">%s</a>' % (_slug(pair.a, pair.b), name)
        parts.append('<tr><td>%d</td><td>%s</td><td>%s</td><td>%d</td><td>%d and %d</td></tr>'
                     % (rank, name, _share(pair, result), pair.shared, pair.sizes[0],
                        pair.sizes[1]))
    parts.append('</tbody></table>')
    if len(pairs) > LISTED:
        parts.append('<p>%d more pairs in similarity.json.</p>' % (len(pairs) - LISTED))
    parts.append('<h2>Shared passages, side by side</h2>')
    parts += [_pair_section(result, pair) for pair in pairs[:DETAILED]]
    parts.append('<h2>Base code: passages in more than %d submissions, never counted</h2>'
                 '<table><thead><tr><th>file (where first seen)</th><th>passages</th>'
                 '<th>most submissions</th><th>examples</th></tr></thead><tbody>'
                 % result.base_limit)
    for rel, count, most, examples in _base_groups(result):
        parts.append('<tr><td>%s</td><td>%d</td><td>%d</td><td>%s</td></tr>' % (
            _e(rel), count, most, ''.join('<pre>%s</pre>' % _e(t) for t in examples)))
    parts.append('</tbody></table></body></html>')
    return ''.join(parts)


def write(out, result, templates=(), references=()):
    """similarity.html, similarity-histogram.svg and similarity.json in ``out``."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, 'similarity-histogram.svg'), 'w') as f:
        f.write(histogram_svg(histogram(all_shares(result)), len(all_shares(result))))
    with open(os.path.join(out, 'similarity.html'), 'w') as f:
        f.write(page(result, templates, references))
    with open(os.path.join(out, 'similarity.json'), 'w') as f:
        json.dump(to_json(result, templates, references), f, indent=1)


def tops(out):
    """{submission: its entry of similarity.json (``top_share``, ``top_with``)}
    of the similarity report in ``out``, or None when there is none."""
    try:
        with open(os.path.join(out, 'similarity.json')) as f:
            return {s['name']: s for s in json.load(f)['submissions']}
    except (OSError, ValueError, KeyError, TypeError):
        return None


# the index's link to similarity.html and its column (report.index writes them)
INDEX_LINK = ('<p><a href="similarity.html">Code shared between submissions</a> '
              '(not a verdict)</p>')
INDEX_HEADING = '<th onclick="sortBy(this)">most shared with</th>'


def index_cell(name, found):
    """The index's cell of ``name``'s highest pair (``found``: :func:`tops`')."""
    top = found.get(name) or {}
    if not top.get('top_with'):
        return '<td data-key="0">—</td>'
    return '<td data-key="%.4f"><a href="similarity.html#%s">%.0f%% %s</a></td>' % (
        top['top_share'], _slug(*sorted((name, top['top_with']))), 100 * top['top_share'],
        _e(top['top_with']))

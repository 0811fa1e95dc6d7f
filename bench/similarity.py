#!/usr/bin/env python3
"""The similarity report's benchmark (issue 42): ``bash tools/run bench
similarity [--counts 30 100 300]``.

For each count it writes a synthetic class made from the fixtures
(test/similarity_fixtures.py's ``make_synthetic``: each submission the
template, the course file most carry, and code of its own, every tenth a
disguised copy of the one before's core), then times ``grade CLASS
--similarity-only`` on it, in this process, and prints the wall time, the
pairs found and whether every planted copy is among the top pairs. The goal:
300 submissions in a few minutes on a 2-core machine. Wall time depends on
what else the machine runs: read it as indicative.

``--small`` measures a class too small to tell the course's code instead
(test/similarity_fixtures.py's ``make_small_class``: three submissions on
the course's template, one independent, two disguised copies of one other
class's code): the figures of its pairs with no template (what the page
would say: it gives none), with ``--template``, and with a profile that
carries the template's fingerprints (``--fingerprint-template``).
"""
import argparse
import json
import os
import shutil
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(REPO, 'test'))
sys.path.insert(0, os.path.join(REPO, 'src'))
import similarity_fixtures  # noqa: E402
from exp_assignment2.grading import cli  # noqa: E402


def measure(count, scratch):
    """(seconds, pairs, planted copies, of them among the top pairs) for ``count``."""
    root = os.path.join(scratch, 'class_%d' % count)
    template, folder = similarity_fixtures.make_synthetic(root, count)
    out = os.path.join(root, 'report')
    start = time.time()
    code = cli.main([folder, '--template', template, '--similarity-only', '--out', out])
    seconds = time.time() - start
    assert code == 0, code
    with open(os.path.join(out, 'similarity.json')) as f:
        pairs = json.load(f)['pairs']
    planted = {('student_%03d' % (n - 1), 'student_%03d' % n) for n in range(9, count, 10)}
    top = {(p['a'], p['b']) for p in pairs[:len(planted)]}
    return seconds, len(pairs), len(planted), len(planted & top)


def measure_small(scratch):
    """{way the template is given: {pair: share}} of the small class; with none,
    the share the page would give were the class not too small."""
    from exp_assignment2.grading.similarity import fingerprints, pairs
    template, folder = similarity_fixtures.make_small_class(os.path.join(scratch, 'small'))
    names = sorted(os.listdir(folder))
    read = [fingerprints.Submission.read(n, os.path.join(folder, n)) for n in names]
    out = {'none (no figure on the page)': {(p.a, p.b): p.share
                                            for p in pairs.compare(read).pairs}}
    profile = os.path.join(scratch, 'course.yaml')
    with open(profile, 'w') as f:
        f.write('base: dog\n')
    assert cli.main(['--fingerprint-template', profile, '--template', template]) == 0
    for way, options in (('--template DIR', ['--template', template]),
                         ("the profile's fingerprints", ['--profile', profile])):
        report = os.path.join(scratch, 'report_%d' % len(out))
        assert cli.main([folder, '--similarity-only', '--out', report] + options) == 0
        with open(os.path.join(report, 'similarity.json')) as f:
            out[way] = {(p['a'], p['b']): p['share'] for p in json.load(f)['pairs']}
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--counts', type=int, nargs='+', default=[30, 100, 300])
    parser.add_argument('--small', action='store_true', help='the small class instead')
    args = parser.parse_args()
    scratch = tempfile.mkdtemp(prefix='exp2-bench-similar-')
    try:
        if args.small:
            for way, shares in measure_small(scratch).items():
                print('%-28s %s' % (way, ', '.join('%s-%s %.1f %%' % (a, b, 100 * share)
                                                   for (a, b), share in sorted(shares.items()))))
            return
        print('submissions  wall s  pairs sharing code  planted copies on top')
        for count in args.counts:
            seconds, pairs, planted, found = measure(count, scratch)
            print('%11d  %6.1f  %18d  %d of %d' % (count, seconds, pairs, found, planted),
                  flush=True)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == '__main__':
    main()

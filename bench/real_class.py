#!/usr/bin/env python3
"""The grader on a real class, against a person's verdicts: ``bash tools/run
bench real-class CLASS [--hand FILE] [--out DIR] [--report-only] [GRADE OPTIONS]``.

CLASS is a folder of real submissions, one folder per profile (``CLASS/dog``,
``CLASS/miro``: each student's repository as handed in, see docs/real_class.md
for how to fetch the class of ``bench/real_class.yaml``). Each profile's folder
is graded with the defaults (``tools/run grade``, the options after CLASS given
to it), then each submission's verdict and check results are compared with the
verdicts a person signed running it by hand (``--hand``, default
``bench/real_class.yaml``): a verdict agrees when the verdict is the same and
every check the person judged (``passed``, ``failed``, ``not judged``; a list of
them where chance decides between them, ``any`` where it decides all) came out
as they said. It prints the agreement ("8 of 10
verdicts as by hand") and each disagreement with its check, the grader's figure
and detail, and the person's reason. ``--report-only`` judges the gradings
already in ``--out`` again from their records (``grade --report-only``: the
judge as it is now, no run done again) and compares them.

It is a benchmark, not a test: it needs the class's repositories (CI has no
network) and takes the time a grading takes.
"""
import argparse
import json
import os
import subprocess
import sys
import time

import yaml

import grade as bench_grade     # bench/grade.py: what a grading cost against what it needed

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
OUTCOMES = ('passed', 'failed', 'not judged', 'any')


def outcome(check):
    """A check's result as a person says it."""
    passed = check.get('passed')
    return 'not judged' if passed is None else 'passed' if passed else 'failed'


JUDGED = ('passed', 'failed_checks')     # the verdicts the checks decide


def compare(hand, graded):
    """[(check or 'verdict', by hand, by the grader, the grader's detail)] where they
    differ, for one submission (``graded``: its summary in report.json, or None). A
    check the person left to chance (``any``: a sleep that comes at random) may turn
    the verdict either way: passed against failed_checks with every other check as by
    hand is as by hand."""
    if graded is None:
        return [('verdict', hand['verdict'], 'not graded', '')]
    out = []
    checks = {c['name']: c for c in graded.get('checks') or []}
    for name, said in (hand.get('checks') or {}).items():
        check = checks.get(name)
        got = outcome(check) if check else 'not run'
        if got not in accepted(said):
            out.append((name, ' or '.join(accepted(said)), got, '%s | %s' % (
                check.get('value'), check.get('detail') or '') if check else ''))
    chance = any(len(accepted(said)) > 1 for said in (hand.get('checks') or {}).values())
    if graded['verdict'] != hand['verdict'] and not (
            chance and not out and {graded['verdict'], hand['verdict']} <= set(JUDGED)):
        out.insert(0, ('verdict', hand['verdict'], graded['verdict'],
                       graded.get('reason') or ''))
    return out


def accepted(said):
    """The outcomes a person's word for a check admits: one, a list of those chance
    decides between (``[passed, not judged]``: it passes whenever the run gives it the
    occasion), or ``any``."""
    if said == 'any':
        return list(OUTCOMES[:3])
    return list(said) if isinstance(said, list) else [said]


def load_hand(path):
    """The person's verdicts: {name: {'profile', 'verdict', 'checks', 'why', ...}}."""
    with open(path) as f:
        data = yaml.safe_load(f)
    for name, hand in data['submissions'].items():
        for check, said in (hand.get('checks') or {}).items():
            if said != 'any' and not set(accepted(said)) <= set(OUTCOMES[:3]):
                raise SystemExit('%s: %s: %s: %r is not one of %s, or a list of them' % (
                    path, name, check, said, ', '.join(OUTCOMES)))
    return data['submissions']


def grade(folder, out, profile, options):
    """Grade one profile's folder with tools/run grade; its exit code."""
    command = ['bash', os.path.join(REPO, 'tools', 'run'), 'grade', folder, '--out', out,
               '--profile', profile] + options
    print('$ ' + ' '.join(command), flush=True)
    return subprocess.call(command)


def report(hand, outs):
    """Print the agreement; the number of verdicts as by hand."""
    graded = {}
    for out in outs:
        path = os.path.join(out, 'report.json')
        if os.path.isfile(path):
            with open(path) as f:
                graded.update({s['name']: s for s in json.load(f)['submissions']})
    same = 0
    for name, said in sorted(hand.items(), key=lambda item: item[0].lower()):
        differ = compare(said, graded.get(name))
        same += not differ
        print('%-16s by hand %-13s grader %-13s %s' % (
            name, said['verdict'], (graded.get(name) or {}).get('verdict', 'not graded'),
            'as by hand' if not differ else 'DIFFERS'))
        for check, mine, theirs, detail in differ:
            print('    %s: by hand %s, grader %s%s' % (check, mine, theirs,
                                                      (': ' + detail[:200]) if detail else ''))
        if differ and said.get('why'):
            print('    by hand: %s' % ' '.join(said['why'].split())[:400])
    print('%d of %d verdicts as by hand' % (same, len(hand)))
    return same


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('classes', help='the class: one folder per profile (dog/, miro/)')
    parser.add_argument('--hand', default=os.path.join(HERE, 'real_class.yaml'))
    parser.add_argument('--out', default='real-class-grading')
    parser.add_argument('--report-only', action='store_true')
    args, options = parser.parse_known_args(argv)
    hand = load_hand(args.hand)
    outs, walls = [], {}
    for profile in sorted({h['profile'] for h in hand.values()}):
        folder = os.path.join(args.classes, profile)
        out = os.path.join(os.path.abspath(args.out), profile)
        outs.append(out)
        if args.report_only:        # judged again from the runs' records, none run again
            if os.path.isdir(out):
                grade(folder, out, profile, options + ['--report-only'])
            continue
        if not os.path.isdir(folder):
            print('%s: no folder of the %s class (docs/real_class.md says how to fetch it)'
                  % (folder, profile))
            continue
        started = time.monotonic()
        grade(folder, out, profile, options)
        walls[out] = time.monotonic() - started
    same = report(hand, outs)
    for out in outs:
        print_cost(out, walls.get(out))
    return 0 if same == len(hand) else 1


def print_cost(out, wall):
    """What the grading in ``out`` cost against the CPU its runs needed; ``wall`` None
    (a grading made earlier): from its runs' records, the first start to the last end."""
    path = os.path.join(out, 'report.json')
    if not os.path.isfile(path):
        return
    with open(path) as f:
        graded = json.load(f)
    runs = graded['runs']
    if wall is None:
        spans = [(r['started'], r['finished']) for r in runs if r.get('started') and
                 r.get('finished')]
        wall = max(b for _, b in spans) - min(a for a, _ in spans) if spans else 0.0
    print('%s: %s' % (os.path.basename(out), bench_grade.class_cost(
        runs, len(graded['submissions']), wall)))
    bench_grade.print_cpu(runs, None, graded['profile'], out)


if __name__ == '__main__':
    sys.exit(main())

"""docs/original_env_supplies.md's table of ROS Noetic desktop-full, package by
package, kept honest: its shape is checked as plain text (every row has one of
the four verdicts, those that are there or stand in say how to check it, those
that are not say why, the counts under it add up), and every check of every
row marked there or stand-in is run inside ``bash tools/run original-env`` on
this machine, where students' code runs: ``import M``, ``rospack find P``, and
``COMPONENTS P`` (what ``find_package(catkin COMPONENTS P)`` would get: CMake
finds P now, or Debian has the ``libP-dev`` that the overlay's build installs
for it). A row that says there of something this machine lacks fails here,
naming the row and what its check said."""
import json
import os
import re
import subprocess
import textwrap

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
DOC = os.path.join(REPO, 'docs', 'original_env_supplies.md')
HEADING = '## ROS Noetic desktop-full, package by package'
WS = os.environ.get('EXP2_WS') or os.path.expanduser('~/.cache/exp_assignment2_ws')
VERDICTS = ('there', 'stand-in', 'not needed', 'missing')
VARIANTS = ('ros_core', 'ros_base', 'robot', 'viz', 'desktop', 'perception', 'simulators',
            'desktop_full')
CHECK = re.compile(r'(import [A-Za-z_][\w.]*|rospack find \w+|COMPONENTS \w+)$')

# Run inside the original-code shell: each check of the JSON list on stdin,
# an import in a fresh interpreter of its own (one import must not help
# another); prints {check: None or why it failed} as JSON.
CHECKER = textwrap.dedent(r'''
    import json, os, subprocess, sys, tempfile
    checks = json.load(sys.stdin)
    results, components = {}, []

    def last_line(proc):
        lines = (proc.stdout + proc.stderr).strip().splitlines()
        return lines[-1] if lines else 'exit status %d' % proc.returncode

    for check in checks:
        kind, _, name = check.partition(' ')
        if kind == 'import':
            cmd = [sys.executable, '-c', 'import ' + name]
        elif kind == 'rospack':
            cmd = ['rospack', 'find', name.split()[-1]]
        else:
            components.append(name)
            continue
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True, cwd='/', timeout=120)
        results[check] = None if proc.returncode == 0 else last_line(proc)
    if components:
        from exp_assignment2.original_env.overlay import debian_packages, stand_ins
        with tempfile.TemporaryDirectory() as probe:
            missing = stand_ins.missing_components(components, probe, dict(os.environ))
        for name in components:
            if missing is None:
                why = 'the CMake probe failed'
            elif name in missing and not debian_packages.candidate(name):
                why = 'CMake does not find it and Debian has no lib%s-dev' % name.replace('_', '-')
            else:
                why = None
            results['COMPONENTS ' + name] = why
    print(json.dumps(results))
''')


def survey():
    """The table's rows as dicts (package, variant, here, from, checks, notes)."""
    with open(DOC, encoding='utf-8') as f:
        text = f.read()
    assert text.count(HEADING) == 1, 'no "%s" section in %s' % (HEADING, DOC)
    section = text.split(HEADING, 1)[1].split('\n## ', 1)[0]
    rows = []
    for line in section.splitlines():
        if not line.startswith('| `'):
            continue
        cells = [c.strip() for c in line.strip().strip('|').split(' | ')]
        assert len(cells) == 6, 'a row of six cells: %s' % line
        package, variant, here, source, checks, notes = cells
        rows.append({'package': package.strip('`'), 'variant': variant, 'here': here,
                     'from': source, 'checks': re.findall(r'`([^`]+)`', checks),
                     'notes': notes, 'line': line, 'text': section})
    return rows


ROWS = survey()


def test_every_row_has_a_verdict_and_says_how_or_why():
    assert len(ROWS) > 150
    names = [r['package'] for r in ROWS]
    assert len(names) == len(set(names)), sorted(n for n in names if names.count(n) > 1)
    for row in ROWS:
        assert row['here'] in VERDICTS, row['line']
        assert row['variant'] in VARIANTS, row['line']
        if row['here'] in ('there', 'stand-in'):
            assert row['checks'] and row['from'] != '—', row['line']
            for check in row['checks']:
                assert CHECK.match(check), 'not a check: %r in %s' % (check, row['line'])
        else:
            assert not row['checks'] and row['notes'], row['line']


def test_the_counts_under_the_table_add_up():
    found = re.search(r'Of its (\d+) packages: (\d+) there, (\d+) stand-in, (\d+) not needed, '
                      r'(\d+) missing\.', ROWS[0]['text'])
    assert found, 'no counts line under the table'
    counted = [len(ROWS)] + [sum(r['here'] == v for r in ROWS) for v in VERDICTS]
    assert [int(n) for n in found.groups()] == counted


def test_the_issues_packages_are_in_the_table():
    here = {r['package']: r['here'] for r in ROWS}
    for name in ('actionlib_tutorials', 'turtlesim', 'turtle_actionlib', 'rospy_tutorials',
                 'roscpp_tutorials', 'laser_assembler', 'theora_image_transport'):
        assert here[name] == 'stand-in'
    # each message stand-in in tools/stand_ins that is part of desktop-full has its row
    for name in os.listdir(os.path.join(REPO, 'tools', 'stand_ins')):
        if name not in ('motion_plan', 'controller_manager_msgs'):   # not desktop-full's
            assert here.get(name) == 'stand-in', name


@pytest.mark.skipif(not os.path.exists(os.path.join(WS, 'devel', 'setup.bash')),
                    reason='no catkin workspace at %s: bash tools/run setup' % WS)
def test_what_the_table_says_is_there_is_there_in_original_env():
    checks = sorted({c for r in ROWS if r['here'] in ('there', 'stand-in') for c in r['checks']})
    env = dict(os.environ, PATH='/usr/bin:' + os.environ.get('PATH', ''))
    proc = subprocess.run(['bash', os.path.join(REPO, 'tools', 'run'), 'original-env',
                           '/usr/bin/python3', '-c', CHECKER],
                          input=json.dumps(checks), stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, env=env, cwd='/',
                          timeout=1800)
    assert proc.returncode == 0, proc.stderr[-3000:]
    results = json.loads(proc.stdout.strip().splitlines()[-1])
    assert sorted(results) == checks
    wrong = ['%s (%s): `%s`: %s' % (r['package'], r['here'], c, results[c])
             for r in ROWS if r['here'] in ('there', 'stand-in') for c in r['checks'] if results[c]]
    assert not wrong, 'rows of the desktop-full table this machine contradicts:\n' + \
        '\n'.join(wrong)

"""The documentation says what the repository has: every relative link and
image in README.md and docs/*.md exists (a heading, for a #fragment), and the
README's launch table gives every argument of every launch file with the
default the file has. Plain files: no ROS, no build."""
import glob
import os
import re
import xml.etree.ElementTree as ET

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
README = os.path.join(REPO, 'README.md')
PAGES = [README] + sorted(glob.glob(os.path.join(REPO, 'docs', '*.md')))
LAUNCH_DIR = os.path.join(REPO, 'launch')
# [text](target) and ![alt](target); a target has no spaces or parentheses
LINK = re.compile(r'!?\[[^\]]*\]\(([^)\s]+)\)')
FENCE = re.compile(r'^```.*?^```', re.S | re.M)
CODE = re.compile(r'`[^`\n]*`')
ARG = re.compile(r'`([A-Za-z_][A-Za-z0-9_]*):=([^`]*)`')


def page_text(path):
    """The page without its code (fenced blocks and inline code spans)."""
    with open(path, encoding='utf-8') as f:
        return CODE.sub('', FENCE.sub('', f.read()))


def slug(heading):
    """A heading's anchor as GitHub makes it."""
    text = heading.strip().lower().replace('`', '')
    return re.sub(r'[^\w\- ]', '', text).replace(' ', '-')


def anchors(path):
    with open(path, encoding='utf-8') as f:
        text = FENCE.sub('', f.read())
    return {slug(m.group(1)) for m in re.finditer(r'^#+\s+(.*)$', text, re.M)}


def relative_links():
    for page in PAGES:
        for target in LINK.findall(page_text(page)):
            if re.match(r'[a-z][a-z0-9+.-]*:', target):      # http:, mailto: ...
                continue
            yield os.path.relpath(page, REPO), target


LINKS = sorted(set(relative_links()))


def test_pages_have_links():
    assert len(LINKS) > 20


@pytest.mark.parametrize('page,target', LINKS, ids=['%s -> %s' % l for l in LINKS])
def test_relative_link_exists(page, target):
    path, _, fragment = target.partition('#')
    base = os.path.dirname(os.path.join(REPO, page))
    resolved = os.path.normpath(os.path.join(base, path)) if path else os.path.join(REPO, page)
    assert os.path.exists(resolved), '%s links to %s, which does not exist' % (page, target)
    if fragment and resolved.endswith('.md'):
        assert fragment in anchors(resolved), \
            '%s links to %s: no heading with that anchor in %s' % (page, target, path or page)


def test_readme_is_short():
    with open(README, encoding='utf-8') as f:
        assert len(f.read().splitlines()) <= 250


def readme_launch_table():
    """{launch file: {argument: default}} from the README's table of launch files."""
    with open(README, encoding='utf-8') as f:
        lines = f.read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith('| launch file |'))
    table = {}
    for line in lines[start + 2:]:
        if not line.startswith('|'):
            break
        cells = [c.strip() for c in line.strip('|').split('|')]
        name = re.search(r'`([\w.]+\.launch)`', cells[0]).group(1)
        args = ARG.findall(cells[-1])
        assert len(args) == len(dict(args)), 'an argument twice in the row of %s' % name
        table[name] = dict(args)
    return table


def launch_arguments(name):
    """The arguments a user can set in a launch file, with their defaults (an
    <arg> with value= is fixed; one with neither must be given)."""
    root = ET.parse(os.path.join(LAUNCH_DIR, name)).getroot()
    return {a.get('name'): a.get('default') for a in root.findall('arg') if a.get('value') is None}


TABLE = readme_launch_table()
LAUNCH_FILES = sorted(os.path.basename(p) for p in glob.glob(os.path.join(LAUNCH_DIR, '*.launch')))


def test_readme_table_lists_every_launch_file():
    assert sorted(TABLE) == LAUNCH_FILES


@pytest.mark.parametrize('name', LAUNCH_FILES)
def test_readme_table_gives_each_argument_and_its_default(name):
    documented = TABLE.get(name, {})
    actual = launch_arguments(name)
    for arg, default in documented.items():
        assert arg in actual, 'README: %s has no argument %r' % (name, arg)
        assert default == (actual[arg] or ''), \
            'README: %s %s:=%s, but the launch file says %r' % (name, arg, default, actual[arg])
    missing = sorted(set(actual) - set(documented))
    assert not missing, 'README: %s leaves out %s' % (name, ', '.join(missing))

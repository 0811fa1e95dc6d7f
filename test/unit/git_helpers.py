"""Git repositories made in a test, as a student's (GitHub Classroom clones a
folder of them): commits at set dates, then, for the hostile ones, a
``.git/config`` and hooks that would leave a mark if anything ran them.

``git`` here is the test's own tool, run on the test's own repositories
with a clean environment (no global or system config); the grader never runs it.
"""
import os
import subprocess

HOSTILE_CONFIG = '''[core]
\tfsmonitor = "touch {mark}/fsmonitor"
\thooksPath = {hooks}
\tsshCommand = "touch {mark}/ssh"
\tpager = "touch {mark}/pager"
[filter "evil"]
\tsmudge = "touch {mark}/smudge"
\tclean = "touch {mark}/clean"
\trequired = true
[include]
\tpath = {include}
[alias]
\tarchive = "!touch {mark}/alias"
'''
HOOK = '#!/bin/sh\ntouch {mark}/hook-$(basename "$0")\n'


def git(repo, *args, when=None, env=None):
    """``git -C repo ARGS`` with a clean environment (and both dates at ``when``)."""
    environment = {'PATH': '/usr/bin:/bin', 'HOME': repo, 'GIT_CONFIG_NOSYSTEM': '1',
                   'GIT_CONFIG_GLOBAL': '/dev/null', 'GIT_AUTHOR_NAME': 'Student',
                   'GIT_AUTHOR_EMAIL': 's@example.org', 'GIT_COMMITTER_NAME': 'Student',
                   'GIT_COMMITTER_EMAIL': 's@example.org', 'TZ': 'UTC'}
    if when:
        environment.update(GIT_AUTHOR_DATE=when, GIT_COMMITTER_DATE=when)
    environment.update(env or {})
    return subprocess.run(['git', '-C', repo] + list(args), env=environment, check=True,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True).stdout.strip()


def write(root, rel, text, mode=0o644):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(text)
    os.chmod(path, mode)


def package_xml(name):
    return ('<package format="2"><name>%s</name><version>0.1.0</version>'
            '<description>x</description><maintainer email="a@b.c">a</maintainer>'
            '<license>MIT</license><buildtool_depend>catkin</buildtool_depend></package>\n'
            % name)


def commit(repo, message, when, files=None):
    """Write ``files`` {rel: text}, then commit them all at ``when`` (ISO 8601
    with a zone): the commit's hash."""
    for rel, text in (files or {}).items():
        write(repo, rel, text, 0o755 if rel.endswith('.py') else 0o644)
    git(repo, 'add', '-A')
    git(repo, 'commit', '-q', '-m', message, when=when)
    return git(repo, 'rev-parse', 'HEAD')


def make_repository(repo, dates, package='dog_pkg'):
    """A repository with one commit at each of ``dates``, each changing the
    node's text (so that packing makes deltas): [hash, ...] oldest first."""
    os.makedirs(repo, exist_ok=True)
    git(repo, 'init', '-q', '-b', 'main')
    hashes = []
    body = ''.join('value_%d = %d * speed + offset  # a line of the node\n' % (i, i)
                   for i in range(200))
    for number, when in enumerate(dates):
        hashes.append(commit(repo, 'commit %d' % (number + 1), when, {
            'package.xml': package_xml(package),
            'scripts/node.py': '#!/usr/bin/env python3\nVERSION = %d\n%s' % (number + 1, body),
            'launch/world.launch': '<launch><!-- version %d --></launch>\n' % (number + 1)}))
    return hashes


def make_hostile(repo, mark):
    """``repo``'s configuration, hooks and attributes made to leave a file in
    ``mark`` if git (or anything honouring them) ran in it."""
    hooks = os.path.join(repo, '.git', 'evil_hooks')
    os.makedirs(hooks, exist_ok=True)
    for name in ('post-checkout', 'pre-commit', 'post-merge', 'reference-transaction',
                 'fsmonitor-watchman', 'pre-auto-gc'):
        for folder in (hooks, os.path.join(repo, '.git', 'hooks')):
            write(folder, name, HOOK.format(mark=mark), 0o755)
    write(repo, '.git/included', '[core]\n\tfsmonitor = "touch %s/included"\n' % mark)
    write(repo, '.git/config', HOSTILE_CONFIG.format(
        mark=mark, hooks=hooks, include=os.path.join(repo, '.git', 'included')))
    write(repo, '.git/info/attributes', '* filter=evil\n')
    write(repo, '.gitattributes', '* filter=evil\n')

"""Which of a repository's packages, and of its README's parts, are this
assignment's (no ROS).

A student may hand in the repository of the whole course: assignment 1,
this one and assignment 3, each with its packages, and one README with a
section for each. A person grading this assignment runs this one's: the
package named as the course's template names it (the profile's
``assignment``: ``exp_assignment2``, or a folder called ``assignment2``), or
the one with the launch file the profile starts, and, of a README in
sections, the sections that start it or what it uses; a section that
starts only the submission's other packages (another assignment's) is left
out, with its heading named.
"""
import os
import re
import shlex

from exp_assignment2.grading.entry import packages as packages_

HEADING = re.compile(r'^(#{1,6})\s+(.*?)\s*#*\s*$|^(.+)\n(?:=+|-+)\s*$', re.M)


def _named(package, names):
    """Is the package, or a folder on its path, called as the assignment is?"""
    wanted = {n.lower() for n in names}
    parts = [package.name] + package.rel.replace(os.sep, '/').split('/')
    return any(p.lower() in wanted for p in parts)


def main_package(found, profile, readme_named=()):
    """The package the run is about (see the module's docstring); the
    README's first named package after the profile's names and launch file."""
    names = profile.get('assignment') or []
    named = [p for p in found if not p.error and _named(p, names)]
    if named:       # the package itself so named first, then one in a folder so named
        return sorted(named, key=lambda p: (p.name.lower() not in {n.lower() for n in names},
                                            p.rel.count(os.sep)))[0]
    launches = [w for c in profile['default_commands'] for w in c.split()
                if w.endswith('.launch')]
    return packages_.main_package(found, launches, readme_named)


def connected(found, main):
    """The names of the packages main uses (transitively) and of those using it."""
    names = {p.name for p in found}
    by_name = {p.name: p for p in found}
    uses = {p.name: packages_.references(p, names) for p in found}
    linked, queue = {main.name}, [main.name]
    while queue:
        name = queue.pop()
        for other in sorted(uses.get(name, ())):
            if other not in linked:
                linked.add(other)
                queue.append(other)
    linked |= {n for n, used in uses.items() if main.name in used and n in by_name}
    return linked


def section_of(text, command):
    """The heading of the README section where ``command`` first appears
    (None before any heading, or not found)."""
    at = text.find(command)
    if at < 0:
        return None
    heading = None
    for match in HEADING.finditer(text):
        if match.start() > at:
            break
        heading = (match.group(2) or match.group(3) or '').strip()
    return heading


def _starts(entry, entries, found, root):
    """The packages (by name, the submission's or not) a README entry starts: a
    ``roslaunch``/``rosrun``'s, a start script's lines'."""
    if entry['kind'] == 'script':
        index = entries.index(entry)
        return set().union(*[_starts(e, entries, found, root) for e in entries
                             if e.get('of') == index] or [set()])
    word = _package_word(entry['command'])
    if word:
        return {word}
    return set(packages_._started(entry['command'], found, root, entry.get('cwd') or ''))


def other_sections(texts, entries, found, main, root=None):
    """{command: why} for the README's commands about another exercise of a
    repository holding several (it has packages main neither uses nor is used by).
    The README's parts are its sections (each README read: the root's, then those on
    the way down to main's folder); a part whose commands start nothing main is
    linked to (only the submission's other packages, or only others' programs such
    as a Stage world of exercise 1) is left out when another part does start main,
    its lines with it. Nothing for a submission of one package, or of packages
    all linked to main."""
    if len(found) < 2 or not texts:
        return {}
    own = {p.name for p in found}
    linked = connected(found, main)
    if not own - linked:            # one assignment in several packages
        return {}
    parts = {}
    for entry in entries:
        if entry.get('kind') in ('ros', 'script') and entry.get('of') is None:
            readme = entry['from']
            parts.setdefault((readme, section_of(texts.get(readme, ''), entry['command'])),
                             []).append(entry)
    started = {key: set().union(*[_starts(e, entries, found, root) for e in listed])
               for key, listed in parts.items()}
    if not any(s & linked for s in started.values()):
        return {}
    out = {}
    for (readme, heading), listed in parts.items():
        if not started[(readme, heading)] or started[(readme, heading)] & linked:
            continue
        where = '`%s` of %s' % (heading, readme) if heading else readme
        for entry in listed:
            out[entry['command']] = ('left out: another part of the README (%s) starts %s, '
                                     'not this assignment\'s %s' % (
                                         where, ', '.join(sorted(started[(readme, heading)])),
                                         main.name))
    return out


def _package_word(command):
    try:
        words = [w for w in shlex.split(command) if not w.startswith('-') and ':=' not in w]
    except ValueError:
        return None
    return words[1] if len(words) > 2 and words[0] in ('roslaunch', 'rosrun') else None

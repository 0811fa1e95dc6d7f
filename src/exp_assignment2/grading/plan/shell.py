"""A line of shell read as ``sh`` splits it (no ROS, nothing run): the
commands of a line with what joins them (``;``, ``&&``, ``||``, ``|``, a
trailing ``&``), quotes kept together, and the words of one command. A README's
code and a start script are read through it (:mod:`~exp_assignment2.grading.plan.commands`,
:mod:`~exp_assignment2.grading.plan.start_script`), so that ``-DCATKIN_WHITELIST_PACKAGES="a;b"`` or
``sh -c "rosrun p a.py; bash"`` is one command, not two.
"""
import re
import shlex

# what a command may be run through and still be itself
PREFIXES = {'nohup', 'setsid', 'exec', 'time', 'command', 'builtin'}
SHELLS = {'sh', 'bash', 'dash', 'zsh', '/bin/sh', '/bin/bash', '/usr/bin/bash',
          '/usr/bin/env'}


def segments(line):
    """[(command text, background)] of one line: split at ``;``, ``&&``,
    ``||``, ``|`` and ``&`` outside quotes and ``$(...)``; ``background``:
    the command ended with a lone ``&`` (the shell goes on at once). A ``#``
    after a space starts a comment."""
    out, current, quote, depth, i = [], [], None, 0, 0
    while i < len(line):
        c = line[i]
        if quote:
            if c == '\\' and quote == '"' and i + 1 < len(line):
                current.append(line[i:i + 2])
                i += 2
                continue
            if c == quote:
                quote = None
        elif c in '"\'':
            quote = c
        elif c == '\\' and i + 1 < len(line):
            current.append(line[i:i + 2])
            i += 2
            continue
        elif line.startswith('$(', i):
            depth += 1
        elif c == ')' and depth:
            depth -= 1
        elif depth == 0 and c == '#' and (i == 0 or line[i - 1].isspace()):
            break
        elif depth == 0 and c in ';&|':
            pair = line[i:i + 2]
            background = c == '&' and pair != '&&' and not line.startswith('>', i + 1) and \
                not (i and line[i - 1] in '>&')
            if c == '&' and not background and pair != '&&':
                current.append(c)           # a redirection such as 2>&1 or &>
                i += 1
                continue
            out.append((''.join(current).strip(), background))
            current = []
            i += 2 if pair in ('&&', '||') else 1
            continue
        current.append(c)
        i += 1
    out.append((''.join(current).strip(), False))
    return [(text, background) for text, background in out if text]


REDIRECTION = re.compile(r'^(?:\d*|&)(?:>>?|<)(&?\d+|&-)?$')     # 2>&1, >, >>, &>, <
REDIRECTION_TO = re.compile(r'^(?:\d*|&)(?:>>?|<)&?\S+$')           # >log.txt, 2>/dev/null


def _substitutions(text):
    """(text with each ``$(...)`` outside single quotes as one placeholder, the
    placeholders' texts): a command substitution is one word to the shell, spaces and
    all (``$(rospack find pkg)/worlds/a.world``), quoted or not."""
    out, found, i, quote = [], [], 0, None
    while i < len(text):
        c = text[i]
        if c == "'" and quote != '"':
            quote = None if quote == "'" else "'"
        elif c == '"' and quote != "'":
            quote = None if quote == '"' else '"'
        elif quote != "'" and text.startswith('$(', i):
            depth, j = 0, i + 1
            while j < len(text):
                depth += {'(': 1, ')': -1}.get(text[j], 0)
                if depth == 0:
                    break
                j += 1
            found.append(text[i:j + 1])
            out.append('\x00%d\x00' % (len(found) - 1))
            i = j + 1
            continue
        out.append(c)
        i += 1
    return ''.join(out), found


def words(text):
    """The words of one command (shlex, as sh), None when its quotes do not
    close; a ``$(...)`` stays whole in its word; leading ``VAR=value``
    settings and prefixes (``nohup``, ``exec``) and redirections (``>
    log.txt``, ``2>&1``) dropped."""
    held, substituted = _substitutions(text)
    try:
        found = [re.sub('\x00(\\d+)\x00', lambda m: substituted[int(m.group(1))], w)
                 for w in shlex.split(held)]
    except ValueError:
        return None
    while found and (re.match(r'^[A-Za-z_]\w*=', found[0]) or found[0] in PREFIXES):
        found = found[1:]
    kept, skip = [], False
    for word in found:
        if skip:
            skip = False
        elif REDIRECTION.match(word):
            skip = not REDIRECTION.match(word).group(1)     # its target is the next word
        elif not REDIRECTION_TO.match(word):
            kept.append(word)
    return kept


def shell_script(found):
    """The script text of ``sh -c "TEXT"`` / ``bash -ic 'TEXT'`` (words), or None."""
    if not found or found[0] not in SHELLS:
        return None
    rest = found[1:]
    if found[0] == '/usr/bin/env' and rest and rest[0] in SHELLS:
        rest = rest[1:]
    for i, word in enumerate(rest):
        if re.match(r'^-\w*c\w*$', word) and i + 1 < len(rest):
            return rest[i + 1]
    return None


def joined(found):
    """Words back into one command line, quoted where a shell needs it."""
    return ' '.join(shlex.quote(w) for w in found)

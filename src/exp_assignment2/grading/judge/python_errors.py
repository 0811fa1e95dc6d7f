"""The Python errors in a run's logs (no ROS): each traceback, and each
syntax error Python printed without one (a node that cannot even be
compiled), once; the quiet endings (Ctrl-C, rospy's shutdown, a peer that
hung up before its handshake) are not errors."""
import re

QUIET_ENDINGS = ('KeyboardInterrupt', 'ROSInterruptException', 'rospy.exceptions.ROSInterrupt',
                 'ROSTimeMovedBackwardsException',
                 # rospy's transport, in any node's log, when a peer hangs up before its
                 # handshake (a probe, a client that exited): nothing the node's code did
                 'ROSHandshakeException: connection from sender terminated before handshake')
TRACEBACK = re.compile(r'^Traceback \(most recent call last\):')
NO_MODULE = re.compile(r"^(?:ModuleNotFoundError|ImportError): No module named '?([\w.]+)'?")
# a script Python cannot compile: '  File "x.py", line 3', its line, carets, then the error
SYNTAX_AT = re.compile(r'^\s*File "(?P<file>[^"]+)", line (?P<line>\d+)\s*$')
SYNTAX_ERROR = re.compile(r'^(?:SyntaxError|IndentationError|TabError): ')


def tracebacks(text, source):
    """[{source, line, summary, excerpt}] of the Python tracebacks in a log's text,
    and of the syntax errors printed without one (their summary names the file and
    line, as Python's str() of the error does)."""
    lines = text.splitlines()
    found, inside = [], set()
    for i, line in enumerate(lines):
        if not TRACEBACK.match(line.strip()):
            continue
        end = i + 1
        while end < len(lines) and (lines[end].startswith((' ', '\t')) or
                                    lines[end].startswith('During handling')):
            end += 1
        inside.update(range(i, end + 1))
        summary = lines[end].strip() if end < len(lines) else 'Traceback'
        found.append({'source': source, 'line': i + 1, 'summary': summary[:300],
                      'excerpt': '\n'.join(lines[max(0, i - 3):end + 1])[-4000:]})
    for i, line in enumerate(lines):
        at = SYNTAX_AT.match(line) if i not in inside else None
        if not at:
            continue
        end = i + 1
        while end < len(lines) and end <= i + 4 and lines[end].startswith((' ', '\t')):
            end += 1
        if end < len(lines) and SYNTAX_ERROR.match(lines[end].strip()):
            summary = '%s (%s, line %s)' % (lines[end].strip(), at.group('file'), at.group('line'))
            found.append({'source': source, 'line': i + 1, 'summary': summary[:300],
                          'excerpt': '\n'.join(lines[i:end + 1])[-4000:]})
    return sorted(found, key=lambda error: error['line'])


def python_errors(logs):
    """The tracebacks of the logs, each once (a node's stdout and its own log repeat them)."""
    seen, errors = set(), []
    for rel, text in logs:
        for error in tracebacks(text, rel):
            if any(error['summary'].startswith(q) or q in error['summary']
                   for q in QUIET_ENDINGS):
                continue
            key = error['excerpt'].split('Traceback', 1)[-1]
            if key in seen:
                continue
            seen.add(key)
            errors.append(error)
    return errors


def name_missing(errors, own):
    """The errors with each module a node could not import named for what it is: one
    of the submission's own packages (``own``, its package names) that the run did not
    build, or one the original environment does not have (a student's machine had it,
    this one has neither it nor a stand-in): never a bare ImportError on the page."""
    out = []
    for error in errors:
        found = NO_MODULE.match(error['summary'])
        if found:
            top = found.group(1).split('.')[0]
            said = ('the submission\'s own package %s, not built for this run (see its '
                    'Packages)' % top if top in own else
                    'missing from the original environment: neither this machine\'s ROS nor '
                    'the package\'s stand-ins have %s (docs/original_env_supplies.md)' % top)
            error = dict(error, summary='%s: %s' % (error['summary'], said))
        out.append(error)
    return out
